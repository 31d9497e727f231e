package org.hapticon.sensor.protocol

import java.io.File

/** Files of the checkout, found from the module directory (where the tests run) or the project root. */
object ModuleFiles {
    fun sensorBridge(path: String): File =
        listOf(File(path), File("sensor-bridge", path)).firstOrNull { it.exists() } ?: throw AssertionError("cannot find sensor-bridge/$path")

    fun testFixtures(path: String): File =
        listOf(File("../test-fixtures", path), File("test-fixtures", path)).firstOrNull { it.exists() }
            ?: throw AssertionError("cannot find test-fixtures/$path")

    fun onPath(program: String): Boolean =
        (System.getenv("PATH") ?: "").split(File.pathSeparator).any { File(it, program).canExecute() }

    /** Runs [command], returning its exit code and its output (stdout and stderr together). */
    fun run(vararg command: String): Pair<Int, String> {
        val process = ProcessBuilder(*command).redirectErrorStream(true).start()
        val output = process.inputStream.bufferedReader().readText()
        return process.waitFor() to output
    }
}
