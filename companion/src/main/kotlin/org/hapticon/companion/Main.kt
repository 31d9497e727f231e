package org.hapticon.companion

import kotlin.system.exitProcess

/** Entry point of the `hapticon` command-line tool; all the work is in [runCli]. */
fun main(args: Array<String>) {
    exitProcess(runCli(args, System.out, System.err))
}
