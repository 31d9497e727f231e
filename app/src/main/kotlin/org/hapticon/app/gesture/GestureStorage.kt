package org.hapticon.app.gesture

import org.hapticon.gesture.Recording
import org.hapticon.gesture.io.RecordingCsv
import org.hapticon.gesture.io.RecordingWav
import org.hapticon.gesture.recognition.GestureLabel
import org.hapticon.gesture.recognition.GestureModel
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import java.io.File
import java.io.InputStream

/** A stored recording: its file [id] (`name[.label].csv`), the user's [name] and an optional gesture [label]. */
data class SavedRecording(val id: String, val name: String, val label: GestureLabel?, val frames: Int, val seconds: Double)

/** The user's saved recordings. */
interface RecordingStore {
    /** Every saved recording, by name. */
    fun list(): List<SavedRecording>

    /** Saves [recording] as [name] (replacing one of the same name and label); [IllegalArgumentException] for a blank name. */
    fun save(name: String, label: GestureLabel?, recording: Recording): SavedRecording

    /** The recording stored as [id]; [IllegalArgumentException] when it is gone or unreadable. */
    fun load(id: String): Recording

    /** Deletes [id]; true when it existed. */
    fun delete(id: String): Boolean
}

/**
 * Recordings as CSV files (the gesture module's [RecordingCsv]) in [directory], one per recording, named
 * `name.csv` or `name.label.csv` (`tap.knock-gentle.csv`): the label in the file name is what
 * `hapticon train` reads, so the folder copied off the phone is a training set.
 */
class FileRecordingStore(private val directory: File) : RecordingStore {
    override fun list(): List<SavedRecording> =
        directory.listFiles { f -> f.isFile && f.name.endsWith(".csv") }.orEmpty()
            .mapNotNull { file -> runCatching { describe(file.name, RecordingCsv.read(file.readText(), file.name)) }.getOrNull() }
            .sortedBy { it.name.lowercase() }

    override fun save(name: String, label: GestureLabel?, recording: Recording): SavedRecording {
        val id = fileName(name, label)
        directory.mkdirs()
        val target = File(directory, id)
        // Write then rename, so a crash mid-write never leaves a half file that list() would skip silently.
        val partial = File(directory, "$id.part")
        partial.writeText(RecordingCsv.write(recording))
        if (!partial.renameTo(target)) {
            target.delete()
            check(partial.renameTo(target)) { "could not store $id" }
        }
        return describe(id, recording)
    }

    override fun load(id: String): Recording {
        val file = File(directory, id)
        require(isOurs(id) && file.isFile) { "no recording $id" }
        return RecordingCsv.read(file.readText(), id)
    }

    override fun delete(id: String): Boolean = isOurs(id) && File(directory, id).delete()

    private fun isOurs(id: String) = id.endsWith(".csv") && '/' !in id && '\\' !in id && !id.startsWith(".")

    private fun describe(id: String, recording: Recording): SavedRecording {
        val stem = id.removeSuffix(".csv")
        val dot = stem.lastIndexOf('.')
        val label = if (dot > 0) GestureLabel.parseOrNull(stem.substring(dot + 1)) else null
        val name = if (label != null) stem.substring(0, dot) else stem
        return SavedRecording(id, name, label, recording.frameCount, recording.durationSeconds)
    }

    companion object {
        /** The file name of [name] with [label]: the name with everything but letters, digits, `-` and `_` replaced by `_`. */
        fun fileName(name: String, label: GestureLabel?): String {
            val safe = name.trim().replace(Regex("[^A-Za-z0-9_-]"), "_")
            require(safe.isNotEmpty()) { "a recording needs a name" }
            require(safe.length <= 64) { "a recording name is at most 64 characters, was ${safe.length}" }
            return if (label == null) "$safe.csv" else "$safe.${label.id}.csv"
        }
    }
}

/** Where the personal recognition model lives: one model at a time. */
interface GestureModelStore {
    /** The stored model, or null when there is none (or it no longer decodes); read from storage on first use, so not on the main thread. */
    val model: StateFlow<GestureModel?>

    /** Stores [model], replacing the previous one. */
    fun save(model: GestureModel)

    /** Decodes [text] (a `hapticon train` model file) and stores it; [IllegalArgumentException] saying what is wrong. */
    fun import(text: String): GestureModel = GestureModel.decode(text).also { save(it) }
}

/** The model as JSON ([GestureModel.encode]) in [file]. */
class FileGestureModelStore(file: File) : GestureModelStore {
    private val store = FileModelStore(file, { GestureModel.decode(it) }) { it.encode() }

    override val model: StateFlow<GestureModel?> get() = store.model

    override fun save(model: GestureModel) = store.save(model)
}

/** One model as text in [file]: read on first use (not on the main thread), replaced whole on [save]. A file that no longer decodes reads as none. */
internal class FileModelStore<M : Any>(private val file: File, private val decode: (String) -> M, private val encode: (M) -> String) {
    private val current by lazy {
        MutableStateFlow(if (file.isFile) runCatching { decode(file.readText()) }.getOrNull() else null)
    }

    /** The stored model, or null. */
    val model: StateFlow<M?> get() = current

    /** Stores [model], replacing the previous one. */
    fun save(model: M) {
        replaceFile(file, encode(model))
        current.value = model
    }
}

/** Writes [text] to [file] through a `.part` file and a rename, so a crash leaves the old file or the new, never half. */
internal fun replaceFile(file: File, text: String) {
    file.parentFile?.mkdirs()
    val partial = File(file.path + ".part")
    partial.writeText(text)
    if (!partial.renameTo(file)) {
        file.delete()
        check(partial.renameTo(file)) { "could not store the model in $file" }
    }
}

/** Reads a picked file as a recording: a WAV (by its RIFF header) or a CSV, with the gesture module's readers. */
object RecordingImport {
    /** Largest file read: 64 MiB (a minute of 8 channels at 1 kHz as CSV is about 10 MiB). */
    const val MAX_BYTES: Int = 64 shl 20

    /** The recording in [input], named [source] in error messages; [IllegalArgumentException] saying what is wrong. */
    fun read(input: InputStream, source: String): Recording {
        val bytes = readLimited(input, MAX_BYTES, source)
        val riff = bytes.size >= 4 && bytes[0] == 'R'.code.toByte() && bytes[1] == 'I'.code.toByte() && bytes[2] == 'F'.code.toByte() && bytes[3] == 'F'.code.toByte()
        return if (riff) RecordingWav.read(bytes.inputStream(), source) else RecordingCsv.read(bytes.toString(Charsets.UTF_8), source)
    }
}

/**
 * The bytes of [input], at most [limit]; [IllegalArgumentException] naming [source] when it is empty or
 * longer. (InputStream.readNBytes needs API 33.)
 */
internal fun readLimited(input: InputStream, limit: Int, source: String): ByteArray {
    val out = java.io.ByteArrayOutputStream()
    val chunk = ByteArray(64 * 1024)
    while (out.size() <= limit) {
        val n = input.read(chunk, 0, minOf(chunk.size, limit + 1 - out.size()))
        if (n < 0) break
        out.write(chunk, 0, n)
    }
    require(out.size() <= limit) { "$source is larger than ${limit shr 20} MiB" }
    require(out.size() > 0) { "$source is empty" }
    return out.toByteArray()
}
