package org.hapticon.companion.sensors

import org.hapticon.companion.cli.UsageException
import org.hapticon.sensor.glove.SensorCsvException
import java.io.File
import java.io.IOException

/** The input files of the sensor commands: every problem becomes a one-line [UsageException] naming the option or file. */
internal object InputFiles {
    /** The file given to `--[option]`; a [UsageException] when it is missing or a directory. */
    fun existing(option: String, path: String): File {
        val file = File(path)
        if (file.isDirectory) throw UsageException("--$option: $file is a directory, not a file")
        if (!file.isFile) throw UsageException("--$option: no such file: $file")
        return file
    }

    /** The text (UTF-8) of the file given to `--[option]`. */
    fun readText(option: String, path: String): String {
        val file = existing(option, path)
        return try {
            file.readText(Charsets.UTF_8)
        } catch (e: IOException) {
            throw UsageException("cannot read $file: ${e.message}")
        }
    }

    /** Runs [parse], turning a bad sensor CSV into a [UsageException] that keeps its `file:line: problem` message. */
    inline fun <T> sensorCsv(parse: () -> T): T = try {
        parse()
    } catch (e: SensorCsvException) {
        throw UsageException(e.message.orEmpty())
    }
}
