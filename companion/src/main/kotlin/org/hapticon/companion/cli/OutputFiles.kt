package org.hapticon.companion.cli

import java.io.BufferedOutputStream
import java.io.File
import java.io.FileOutputStream
import java.io.IOException
import java.io.OutputStream

/** Writes output files so that every I/O problem becomes a one-line [UsageException] naming the file. */
object OutputFiles {
    /**
     * Opens [file], lets [write] fill it, and closes it. A file that fails part-way is deleted, so no
     * truncated WAV or PNG is left behind looking valid. Throws [UsageException] when [file] cannot be
     * written.
     */
    fun write(file: File, write: (OutputStream) -> Unit) {
        checkWritable(file)
        val stream = try {
            FileOutputStream(file)
        } catch (e: IOException) {
            throw UsageException("cannot write $file: ${e.message}")
        }
        var complete = false
        try {
            BufferedOutputStream(stream, BUFFER_BYTES).use(write)
            complete = true
        } catch (e: IOException) {
            throw UsageException("cannot write $file: ${e.message}")
        } finally {
            if (!complete) file.delete()
        }
    }

    /** Creates [dir] (and its parents) if needed; throws [UsageException] when that is impossible. */
    fun ensureDirectory(dir: File) {
        if (dir.isDirectory) return
        if (dir.exists()) throw UsageException("cannot write into $dir: it is not a directory")
        if (!dir.mkdirs()) throw UsageException("cannot create directory $dir")
    }

    /** Clear messages for the common cases, before the less readable ones FileOutputStream gives. */
    private fun checkWritable(file: File) {
        if (file.isDirectory) throw UsageException("cannot write $file: it is a directory")
        val parent = file.absoluteFile.parentFile
        if (parent != null && !parent.isDirectory) throw UsageException("cannot write $file: directory $parent does not exist")
    }

    private const val BUFFER_BYTES = 1 shl 16
}
