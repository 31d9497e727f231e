package org.hapticon.app.feature.study

import android.content.Context
import android.content.Intent
import android.net.Uri
import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import com.sun.net.httpserver.HttpServer
import java.io.File
import java.net.InetSocketAddress
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.flow.filterIsInstance
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.advanceUntilIdle
import kotlinx.coroutines.test.resetMain
import kotlinx.coroutines.test.runTest
import kotlinx.coroutines.test.setMain
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.study.HttpResultUploader
import org.hapticon.app.study.MaskingSetting
import org.hapticon.app.study.NoiseColor
import org.hapticon.app.study.PinGate
import org.hapticon.app.study.RoomStudyRepository
import org.hapticon.app.study.SharedPreferencesStudySettings
import org.hapticon.app.study.StoredProtocol
import org.hapticon.app.study.StudyComponent
import org.hapticon.app.study.StudyExporter
import org.hapticon.app.study.StudySettingsRepository
import org.hapticon.app.study.TestMaskingNoise
import org.hapticon.app.study.TestStudySettings
import org.hapticon.app.study.TickingClock
import org.hapticon.app.study.UploadResult
import org.hapticon.study.OriginatingStudy
import org.hapticon.study.export.ResponseCsv
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Before
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/** The researcher side: PIN gate, headphone warning, export and share, upload to a stub collector. */
@OptIn(ExperimentalCoroutinesApi::class)
@RunWith(RobolectricTestRunner::class)
class StudyResearcherTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val dispatcher = StandardTestDispatcher()
    private val exports = File(context.cacheDir, "exports")
    private lateinit var db: HapticonDatabase
    private val settings = TestStudySettings()
    private val noise = TestMaskingNoise()
    private var headphones = false
    private val uploads = ArrayList<String>()
    private var collector: HttpServer? = null

    @Before
    fun setUp() {
        Dispatchers.setMain(dispatcher)
        exports.deleteRecursively()
        db = Room.inMemoryDatabaseBuilder(context, HapticonDatabase::class.java).build()
    }

    @After
    fun tearDown() {
        collector?.stop(0)
        db.close()
        Dispatchers.resetMain()
    }

    private fun component(
        pin: PinGate = PinGate(context.getSharedPreferences("researcher-test", Context.MODE_PRIVATE).also { it.edit().clear().commit() }),
        settings: StudySettingsRepository = this.settings,
    ) =
        StudyComponent(
            repository = RoomStudyRepository(db),
            settings = settings,
            pin = pin,
            noise = noise,
            headphones = { headphones },
            exporter = StudyExporter(exports, clock = { 1_700_000_999_000L }),
            uploader = HttpResultUploader(connectTimeoutMillis = 2_000, readTimeoutMillis = 2_000),
            clock = TickingClock(),
        )

    /**
     * A stub of `hapticon collect`: 200 for a CSV with the right header, else 400 naming the line. With
     * [uploadToken], its answers to other tokens as the collector gives them: 401 for none or an unknown one, 403
     * for [DOWNLOAD_TOKEN] (a real token of the study, but of the download role).
     */
    private fun startCollector(uploadToken: String? = null): String {
        val server = HttpServer.create(InetSocketAddress("127.0.0.1", 0), 0)
        server.createContext("/v1/results") { exchange ->
            val body = exchange.requestBody.readBytes().decodeToString()
            val authorization = exchange.requestHeaders.getFirst("Authorization")
            uploads += "${exchange.requestMethod} ${exchange.requestHeaders.getFirst("Content-Type")} " +
                "${exchange.requestHeaders.getFirst("X-Study-Id")} $authorization ${body.length}"
            val (status, answer) = when {
                uploadToken != null && authorization == null -> 401 to "{\"error\":\"missing bearer token\"}"
                uploadToken != null && authorization == "Bearer $DOWNLOAD_TOKEN" -> 403 to "{\"error\":\"this token may only download, not upload\"}"
                uploadToken != null && authorization != "Bearer $uploadToken" -> 401 to "{\"error\":\"unknown or revoked token\"}"
                body.startsWith(ResponseCsv.HEADER) -> 200 to "{\"stored\": 1}"
                else -> 400 to "{\"error\": \"line 1: header must be exactly ${ResponseCsv.HEADER.take(8)}...\"}"
            }
            val bytes = answer.toByteArray()
            exchange.sendResponseHeaders(status, bytes.size.toLong())
            exchange.responseBody.use { it.write(bytes) }
        }
        server.start()
        collector = server
        return "http://127.0.0.1:${server.address.port}/"
    }

    @Test
    fun pinGate_firstUseSetsThePin_wrongPinRefused_rightPinOpens() = runTest(dispatcher) {
        val vm = ResearcherViewModel(component(), hashing = dispatcher)
        assertEquals(LockState.SET_PIN, vm.uiState.value.lock)
        vm.setPin("1234", "1243")
        assertEquals(LockState.SET_PIN, vm.uiState.first { it.pinError != null }.lock)
        assertEquals("the two PINs differ", vm.uiState.value.pinError)
        vm.setPin("12", "12")
        assertEquals(LockState.SET_PIN, vm.uiState.first { it.pinError == "the PIN must be 4 to 12 digits" }.lock)
        vm.setPin("1234", "1234")
        assertNull(vm.uiState.first { it.lock == LockState.UNLOCKED }.pinError)

        vm.lock()
        vm.unlock("4321").join()
        assertEquals(LockState.LOCKED, vm.uiState.first { it.pinError == "wrong PIN" }.lock)
        vm.unlock("1234").join()
        assertNull(vm.uiState.first { it.lock == LockState.UNLOCKED }.pinError)
    }

    @Test
    fun startSession_maskingWithoutHeadphones_warnsFirst_thenProceedsAndLeavingNeedsThePin() = runTest(dispatcher) {
        val study = component()
        study.repository.saveProtocol(StoredProtocol(OriginatingStudy.PROTOCOL.copy(id = "masked"), masking = MaskingSetting(NoiseColor.PINK, -30.0)))
        val vm = ResearcherViewModel(study, hashing = dispatcher)
        vm.setPin("1234", "1234")
        vm.select("masked")

        vm.startSession().join()
        vm.ready { it.headphoneWarning }
        assertNull(settings.preferences.value.activeSessionId)

        vm.startSession(ignoreHeadphones = true).join()
        val active = settings.preferences.value.activeSessionId!!
        // The active session is set last, after the warning is cleared and the screen locked.
        val started = vm.ready { it.nextParticipant == "P001-D" && it.activeSessionId == active }
        assertFalse(started.headphoneWarning)
        assertEquals(LockState.LOCKED, started.lock)
        assertEquals("P000-A", study.repository.session(active)!!.participant)

        vm.exitSession("0000").join()
        assertEquals(active, settings.preferences.value.activeSessionId)
        vm.exitSession("1234").join()
        assertNull(settings.preferences.value.activeSessionId)

        headphones = true
        vm.startSession().join()
        assertFalse("with headphones there is nothing to warn about", vm.ready { it.activeSessionId != null }.headphoneWarning)
        assertEquals("P001-D", study.repository.session(settings.preferences.value.activeSessionId!!)!!.participant)
    }

    @Test
    fun export_writesCsvAndJsonToCacheExports_andBuildsTheShareIntent() = runTest(dispatcher) {
        val study = component()
        val record = study.repository.startSession(StoredProtocol.DEFAULT, 1_700_000_000_000L)
        val vm = ResearcherViewModel(study, hashing = dispatcher)
        vm.export().join()

        val export = vm.ready { it.export != null }.export!!
        assertEquals(File(exports, "hapticon-icons-r1-1700000999000.csv"), export.csvFile)
        assertEquals(File(exports, "hapticon-icons-r1-1700000999000.json"), export.jsonFile)
        assertEquals("${ResponseCsv.HEADER}\r\n", export.csvFile.readText())
        assertTrue(export.jsonFile.readText().contains("\"${record.participant}\""))
        assertEquals(listOf("P000-A: log intact"), export.checks.map { "${it.participant}: ${it.summary}" })
        assertEquals("exported 0 rows", vm.now.message)

        val intent = StudyExporter.shareIntent(context, export.csvFile, "text/csv")
        assertEquals(Intent.ACTION_SEND, intent.action)
        assertEquals("text/csv", intent.type)
        @Suppress("DEPRECATION")
        val uri = intent.getParcelableExtra<Uri>(Intent.EXTRA_STREAM)!!
        assertEquals("content://org.hapticon.app.exports/exports/hapticon-icons-r1-1700000999000.csv", uri.toString())
        assertTrue(intent.flags and Intent.FLAG_GRANT_READ_URI_PERMISSION != 0)
        assertEquals("hapticon-icons-r1-1700000999000.csv", intent.getStringExtra(Intent.EXTRA_SUBJECT))
    }

    @Test
    fun upload_200_isDone_400_showsTheCollectorsError() = runBlocking {
        val url = startCollector()
        val uploader = HttpResultUploader(2_000, 2_000)
        val csv = "${ResponseCsv.HEADER}\r\nrow\r\n"

        assertEquals(UploadResult.Uploaded("uploaded to 127.0.0.1"), uploader.upload(url, "s3cret", "hapticon-icons", csv))
        assertEquals(UploadResult.Failed("collector answered 400: line 1: header must be exactly study_id..."), uploader.upload(url, "", "hapticon-icons", "bad\r\n"))
        assertEquals(
            listOf("POST text/csv; charset=utf-8 hapticon-icons Bearer s3cret ${csv.length}", "POST text/csv; charset=utf-8 hapticon-icons null 5"),
            uploads,
        )
        assertEquals(
            UploadResult.Failed("the collector URL must start with http:// or https://, got \"ftp://x\""),
            uploader.upload("ftp://x", "", "s", csv),
        )
    }

    @Test
    fun upload_collectorDown_failureShown_retrySendsTheSameExport() = runTest(dispatcher) {
        val study = component()
        study.repository.startSession(StoredProtocol.DEFAULT, 1_700_000_000_000L)
        val vm = ResearcherViewModel(study, hashing = dispatcher)
        // A port nobody listens on: the server is started and stopped to get one.
        val down = HttpServer.create(InetSocketAddress("127.0.0.1", 0), 0).let { val port = it.address.port; it.stop(0); port }
        vm.setCollector("http://127.0.0.1:$down", "")
        vm.upload().join()
        val failed = vm.ready { it.upload is UploadState.Failed }.upload as UploadState.Failed
        assertTrue(failed.message, failed.message.startsWith("upload failed: "))
        val export = vm.now.export!!
        assertTrue("the export stays for the retry", export.csvFile.isFile)

        vm.setCollector(startCollector(), "")
        vm.upload().join()
        assertEquals(UploadState.Done("0 rows uploaded to 127.0.0.1"), vm.ready { it.upload is UploadState.Done }.upload)
        assertEquals(export, vm.now.export)
        assertEquals(listOf("POST text/csv; charset=utf-8 hapticon-icons null ${export.csv.length}"), uploads)
    }

    @Test
    fun upload_tokenFromTheSettings_sentAsBearer_401And403SayWhichTokenAndNothingIsLost() = runTest(dispatcher) {
        val prefs = context.getSharedPreferences("researcher-token-test", Context.MODE_PRIVATE).also { it.edit().clear().commit() }
        val study = component(settings = SharedPreferencesStudySettings(prefs))
        study.repository.startSession(StoredProtocol.DEFAULT, 1_700_000_000_000L)
        val vm = ResearcherViewModel(study, hashing = dispatcher)
        val url = startCollector(uploadToken = UPLOAD_TOKEN)
        // The uploader runs on Dispatchers.IO (joined); the state then reaches uiState on the test dispatcher.
        suspend fun uploadState(): UploadState {
            vm.upload().join()
            advanceUntilIdle()
            return vm.now.upload
        }
        fun failed(message: String) = UploadState.Failed("$message: enter the upload token of study 'hapticon-icons' and upload again")

        // Export first, so that an export problem shows as itself rather than as an upload that never ran.
        vm.export().join()
        // uiState combines Room flows, which first emit from Room's own threads: wait for them, not for the scheduler.
        val export = vm.ready { it.export != null || it.message != null }.let { checkNotNull(it.export) { "no export: ${it.message}" } }
        vm.setCollector(url, "")
        assertEquals(failed("the collector needs a token"), uploadState())
        assertEquals(export, vm.now.export)
        vm.setCollector(url, DOWNLOAD_TOKEN)
        assertEquals(failed("the collector refused this token (this token may only download, not upload)"), uploadState())
        vm.setCollector(url, "hct1.ffffffffffffffff.wrong")
        assertEquals(failed("the collector does not know this token (revoked, mistyped or from another collector)"), uploadState())

        vm.setCollector(" $url ", "  $UPLOAD_TOKEN  ")
        // Saved trimmed, where a restarted app reads it back.
        assertEquals(UPLOAD_TOKEN, SharedPreferencesStudySettings(prefs).preferences.value.collectorToken)
        advanceUntilIdle()
        assertEquals(UPLOAD_TOKEN, vm.now.collectorToken)
        assertEquals(UploadState.Done("0 rows uploaded to 127.0.0.1"), uploadState())
        // The refused uploads lost nothing: the same export went out each time, and the last with the token.
        assertEquals(export, vm.now.export)
        assertTrue(export.csvFile.isFile)
        val sent = "POST text/csv; charset=utf-8 hapticon-icons"
        assertEquals(
            listOf("$sent null", "$sent Bearer $DOWNLOAD_TOKEN", "$sent Bearer hct1.ffffffffffffffff.wrong", "$sent Bearer $UPLOAD_TOKEN").map { "$it ${export.csv.length}" },
            uploads,
        )
    }

    private companion object {
        const val UPLOAD_TOKEN = "hct1.0123456789abcdef.AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA"
        const val DOWNLOAD_TOKEN = "hct1.fedcba9876543210.BBBBBBBBBBBBBBBBBBBBBBBBBBBBBBBBBBBBBBBBBBB"
    }

    // The researcher's state once Room and the settings have answered (before, it is Loading: only the PIN gate).
    private suspend fun ResearcherViewModel.ready(predicate: (ResearcherUiState.Success) -> Boolean) =
        uiState.filterIsInstance<ResearcherUiState.Success>().first(predicate)

    private val ResearcherViewModel.now: ResearcherUiState.Success get() = uiState.value as ResearcherUiState.Success
}
