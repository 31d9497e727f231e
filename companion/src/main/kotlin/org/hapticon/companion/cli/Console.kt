package org.hapticon.companion.cli

import java.io.PrintStream

/** Where a command writes: results to [out], progress and diagnostics to [err]. */
class Console(val out: PrintStream, val err: PrintStream)
