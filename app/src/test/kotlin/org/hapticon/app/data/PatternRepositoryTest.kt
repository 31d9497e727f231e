package org.hapticon.app.data

import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.test.runTest
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.data.database.PatternEntity
import org.hapticon.app.data.database.patternToJson
import org.hapticon.core.pattern.AmplitudeKey
import org.hapticon.core.pattern.FrequencyKey
import org.hapticon.core.pattern.FrequencyMapping
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PatternFormat
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

@RunWith(RobolectricTestRunner::class)
class PatternRepositoryTest {
    private val db = Room.inMemoryDatabaseBuilder(ApplicationProvider.getApplicationContext(), HapticonDatabase::class.java)
        .allowMainThreadQueries().build()
    private val repository = RoomPatternRepository(db.patternDao(), clock = { 1_000 })

    private val haptic = """{"version":{"major":1,"minor":0,"patch":0},"signals":{"continuous":{"envelopes":{""" +
        """"amplitude":[{"time":0,"amplitude":0.5},{"time":0.25,"amplitude":0}],"frequency":[{"time":0,"frequency":0},{"time":0.25,"frequency":1}]}}}}"""

    @After
    fun tearDown() = db.close()

    @Test
    fun import_metaHaptic_storedWithItsFileNameAsSource() = runTest {
        val outcome = repository.import(haptic.toByteArray(), "buzz.haptic", taken = emptySet()) as PatternImportOutcome.Imported
        val expected = HapticPattern(
            "buzz", listOf(AmplitudeKey(0.0, 0.5), AmplitudeKey(0.25, 0.0)),
            listOf(FrequencyKey(0.0, FrequencyMapping.DEFAULT.minHz), FrequencyKey(0.25, FrequencyMapping.DEFAULT.maxHz)),
        )
        assertEquals(expected.amplitude, outcome.pattern.amplitude)
        assertEquals(listOf(PatternEntity("buzz", patternToJson(outcome.pattern), "buzz.haptic", 1_000)), db.patternDao().patterns().first())
        assertEquals(FrequencyMapping.DEFAULT.maxHz, outcome.pattern.frequency.last().hertz, 1e-9)
    }

    @Test
    fun import_sameNameTwice_secondGetsAFreeNameAndNothingIsOverwritten() = runTest {
        repository.import(haptic.toByteArray(), "buzz.haptic", taken = emptySet())
        val second = repository.import(haptic.toByteArray(), "buzz.haptic", taken = setOf("buzz")) as PatternImportOutcome.Imported
        assertEquals("buzz 2", second.pattern.name)
        assertEquals(listOf("buzz", "buzz 2"), repository.patterns().first().map { it.pattern.name })
    }

    @Test
    fun import_hostileFiles_oneLineErrorAndNothingStored() = runTest {
        val hostile = mapOf(
            "inf.json" to """{"schema":"hapticon.pattern","version":1,"name":"p","amplitude":[{"time":0,"amplitude":1e999}],"frequency":[{"time":0,"hertz":150}]}""",
            "long.ahap" to """{"Pattern":[{"Event":{"Time":0,"EventType":"HapticContinuous","EventDuration":1e9,"EventParameters":[]}}]}""",
            "nan.haptic" to """{"version":{"major":1},"signals":{"continuous":{"envelopes":{"amplitude":[{"time":NaN,"amplitude":0.5}]}}}}""",
            "keys.json" to """{"schema":"hapticon.pattern","version":1,"name":"p","amplitude":[""" +
                (0 until 5000).joinToString(",") { """{"time":${it * 0.001},"amplitude":0.5}""" } + """],"frequency":[{"time":0,"hertz":150}]}""",
        )
        for ((name, text) in hostile) {
            val failed = repository.import(text.toByteArray(), name, emptySet()) as? PatternImportOutcome.Failed
                ?: throw AssertionError("$name was imported")
            assertTrue(failed.message, failed.message.startsWith("$name: ") && '\n' !in failed.message)
        }
        val huge = ByteArray(2 shl 20) { ' '.code.toByte() }
        val tooLarge = repository.import(huge, "huge.json", emptySet()) as PatternImportOutcome.Failed
        assertEquals("huge.json: 2097152 bytes is larger than a pattern file may be (1048576 bytes)", tooLarge.message)
        assertEquals(emptyList<StoredPattern>(), repository.patterns().first())
    }

    @Test
    fun export_eachFormat_readsBackToTheSameTiming() = runTest {
        val outcome = repository.import(haptic.toByteArray(), "buzz.haptic", taken = emptySet()) as PatternImportOutcome.Imported
        for (format in PatternFormat.entries) {
            val text = repository.export(outcome.pattern, format).text
            val back = (repository.import(text.toByteArray(), "back.${format.extension}", setOf("buzz", "back", "back 2", "back 3"))
                as PatternImportOutcome.Imported).pattern
            assertEquals(format.name, outcome.pattern.duration, back.duration, 0.001)
        }
    }
}
