package org.hapticon.companion.board

import java.io.IOException
import java.nio.ByteBuffer
import java.nio.channels.FileChannel
import java.nio.file.FileAlreadyExistsException
import java.nio.file.FileSystemException
import java.nio.file.Files
import java.nio.file.NoSuchFileException
import java.nio.file.Path
import java.nio.file.StandardCopyOption
import java.nio.file.StandardOpenOption
import org.hapticon.companion.cli.UsageException
import org.hapticon.sensor.electrotactile.CalibrationFile
import org.hapticon.sensor.electrotactile.CalibrationFileException
import org.hapticon.sensor.electrotactile.StoredCalibration

/**
 * The calibration files of `hapticon board calibrate --save` and `board set --calibration` on disk; the format is
 * sensor-bridge's [CalibrationFile] (`hapticon.electrotactile-calibration`). Every problem is a one-line
 * [UsageException] naming the file.
 *
 * Writing never leaves half a file: the text goes to a temporary file in the same directory (created by
 * `Files.createTempFile`, so readable by this user only, as a participant's file should be), forced to the disk,
 * then published in one step. Without `force` it is published with `Files.createLink`, which fails when the name
 * exists (link(2) is atomic, so a file that appears during a long calibration is not replaced either); where the
 * file system has no hard links, `Files.move` without `REPLACE_EXISTING`, which refuses an existing name too. With
 * `force` it is `Files.move(ATOMIC_MOVE)`, rename(2), which replaces the old file whole.
 */
internal object CalibrationFiles {
    /**
     * Refuses, before anything is sent to a board, a [path] that could not be saved: an existing file without
     * [force], a directory, a missing directory.
     */
    fun checkCanSave(path: Path, force: Boolean) {
        if (Files.isDirectory(path)) throw UsageException("--save $path is a directory: give a file name")
        if (Files.exists(path) && !force) throw UsageException(exists(path))
        val dir = directoryOf(path)
        if (!Files.isDirectory(dir)) throw UsageException("--save $path: the directory $dir does not exist")
        if (!Files.isWritable(dir)) throw UsageException("--save $path: the directory $dir is not writable")
    }

    /** Writes [calibration] to [path] atomically (see the class comment); replaces an existing file only with [force]. */
    fun save(path: Path, calibration: StoredCalibration, force: Boolean) {
        val bytes = CalibrationFile.encode(calibration).toByteArray(Charsets.UTF_8)
        var temporary: Path? = null
        try {
            temporary = Files.createTempFile(directoryOf(path), ".${path.fileName}.", ".part")
            FileChannel.open(temporary, StandardOpenOption.WRITE).use { channel ->
                val buffer = ByteBuffer.wrap(bytes)
                while (buffer.hasRemaining()) channel.write(buffer)
                channel.force(true)
            }
            if (force) Files.move(temporary, path, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING) else publishNew(temporary, path)
        } catch (e: FileAlreadyExistsException) {
            throw UsageException(exists(path))
        } catch (e: IOException) {
            throw UsageException("cannot write $path: ${e.message ?: e.javaClass.simpleName}: nothing written")
        } finally {
            temporary?.let { runCatching { Files.deleteIfExists(it) } }
        }
    }

    /**
     * The calibration in [path], read strictly ([CalibrationFile.decode]).
     * @throws UsageException `FILE: member: problem`, or why the file cannot be read.
     */
    fun read(path: Path): StoredCalibration {
        val bytes = try {
            if (Files.size(path) > CalibrationFile.MAX_BYTES) throw UsageException("$path: larger than ${CalibrationFile.MAX_BYTES} bytes: not a calibration file")
            Files.readAllBytes(path)
        } catch (e: NoSuchFileException) {
            throw UsageException("$path: no such file")
        } catch (e: IOException) {
            throw UsageException("$path: cannot read: ${e.message ?: e.javaClass.simpleName}")
        }
        return try {
            CalibrationFile.decode(bytes)
        } catch (e: CalibrationFileException) {
            throw UsageException("$path: ${e.message}")
        }
    }

    private fun publishNew(temporary: Path, path: Path) {
        try {
            Files.createLink(path, temporary)
        } catch (e: FileAlreadyExistsException) {
            throw e
        } catch (e: UnsupportedOperationException) {
            Files.move(temporary, path)
        } catch (e: FileSystemException) {
            // No hard links here (FAT, some network shares): a move that refuses an existing name.
            Files.move(temporary, path)
        }
    }

    private fun directoryOf(path: Path): Path = path.toAbsolutePath().parent

    private fun exists(path: Path) = "$path already exists: nothing written (give --force to replace it, or another file name)"
}
