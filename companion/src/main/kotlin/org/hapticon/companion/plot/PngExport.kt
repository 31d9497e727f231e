package org.hapticon.companion.plot

import org.hapticon.companion.cli.OutputFiles
import java.awt.image.BufferedImage
import java.io.File
import javax.imageio.ImageIO

/** Writes images as PNG files. */
object PngExport {
    init {
        ImageIO.setUseCache(false) // encode in memory rather than through a temporary file
    }

    /**
     * Writes [image] to [file] as PNG and returns a one-line summary. Throws
     * [org.hapticon.companion.cli.UsageException] when the file cannot be written.
     */
    fun write(image: BufferedImage, file: File): String {
        OutputFiles.write(file) { out ->
            // Every JDK ships a PNG writer; its absence is a broken runtime, not a user mistake.
            check(ImageIO.write(image, "png", out)) { "no PNG encoder available" }
        }
        return "wrote $file: ${image.width}×${image.height} PNG"
    }
}
