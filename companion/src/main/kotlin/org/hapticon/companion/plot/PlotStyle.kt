package org.hapticon.companion.plot

import java.awt.BasicStroke
import java.awt.Color
import java.awt.Font
import java.awt.Graphics2D
import java.awt.RenderingHints
import java.awt.image.BufferedImage

/** Colours, fonts and strokes shared by every plot, so all pictures look alike. */
object PlotStyle {
    val BACKGROUND: Color = Color.WHITE
    val GRID: Color = Color(232, 232, 232)
    val AXIS: Color = Color(110, 110, 110)
    val TEXT: Color = Color(30, 30, 30)
    val MUTED_TEXT: Color = Color(95, 95, 95)

    /** The carrier waveform band. */
    val WAVEFORM: Color = Color(140, 185, 232)

    /** The envelope over the waveform. */
    val ENVELOPE: Color = Color(200, 30, 45)

    /** The paper model in comparisons. */
    val PAPER: Color = Color(31, 119, 180)

    /** The Processing model in comparisons. */
    val PROCESSING: Color = Color(245, 130, 20)

    val TITLE_FONT: Font = Font(Font.SANS_SERIF, Font.BOLD, 18)
    val SUBTITLE_FONT: Font = Font(Font.SANS_SERIF, Font.PLAIN, 13)
    val LABEL_FONT: Font = Font(Font.SANS_SERIF, Font.PLAIN, 13)
    val TICK_FONT: Font = Font(Font.SANS_SERIF, Font.PLAIN, 12)

    val THIN: BasicStroke = BasicStroke(1f)
    val CURVE: BasicStroke = BasicStroke(2f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND)
    val THICK_CURVE: BasicStroke = BasicStroke(3f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND)

    /** A white RGB image of [width] × [height] and an antialiased graphics context on it; dispose it when done. */
    fun canvas(width: Int, height: Int): Pair<BufferedImage, Graphics2D> {
        val image = BufferedImage(width, height, BufferedImage.TYPE_INT_RGB)
        val g = image.createGraphics()
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON)
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON)
        g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE)
        g.color = BACKGROUND
        g.fillRect(0, 0, width, height)
        return image to g
    }
}
