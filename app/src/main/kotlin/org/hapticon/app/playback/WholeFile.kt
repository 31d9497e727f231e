package org.hapticon.app.playback

import java.io.File
import java.io.IOException
import java.io.OutputStream

/**
 * Writes [file] (creating its directory) through a `.part` file beside it and a rename, so a player never
 * opens a half-written file under [file]'s name.
 * @throws IOException when the directory cannot be made or the file cannot be written or renamed.
 */
@Throws(IOException::class)
internal fun writeWholeFile(file: File, write: (OutputStream) -> Unit) {
    val directory = file.absoluteFile.parentFile
    if (!directory.isDirectory && !directory.mkdirs()) throw IOException("cannot create $directory")
    val partial = File(directory, "${file.name}.part")
    partial.outputStream().buffered().use(write)
    if (!partial.renameTo(file)) throw IOException("cannot rename $partial")
}
