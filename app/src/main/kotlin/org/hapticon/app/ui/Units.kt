package org.hapticon.app.ui

private val NUMBER_THEN_UNIT = Regex("""(\d) (ms|s|Hz|kHz|mA|dp|%)(?![\p{L}])""")

/**
 * [text] with a no-break space between every number and its unit ("20 ms", "1 s", "147 Hz"), so a narrow line
 * wraps before the number instead of leaving "20" at the end of one line and "ms" at the start of the next.
 * Display only: view models keep plain spaces, and this is applied where the line is drawn.
 */
fun keepUnitsWithNumbers(text: String): String = NUMBER_THEN_UNIT.replace(text, "$1\u00A0$2")
