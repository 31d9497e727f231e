package org.hapticon.study.analysis

import org.junit.Assert.assertEquals
import org.junit.Assert.fail
import org.junit.Assume.assumeTrue
import java.io.File
import java.util.concurrent.TimeUnit

/**
 * Base R (Debian's r-base-core) as a test-time oracle. CI (CI=true) installs it (.ci/run) and must run these tests,
 * so there a missing `Rscript` fails the test; elsewhere it is skipped with one line saying how to install it.
 */
internal object RScript {
    /** Skips the calling test when Rscript is not installed, or fails it on CI. */
    fun assumeInstalled(): File {
        find()?.let { return it }
        val message = "Rscript not installed (apt-get install r-base-core): the R reference test is skipped"
        if (System.getenv("CI") == "true") fail("$message; CI must run it")
        System.err.println(message)
        assumeTrue(message, false)
        throw AssertionError("unreachable")
    }

    /** Runs the test resource [script] with [args] in [dir]; returns its standard output lines. Fails on a non-zero exit. */
    fun run(dir: File, script: String, vararg args: String): List<String> {
        val file = File(dir, script)
        file.writeBytes(RScript::class.java.getResourceAsStream(script)!!.use { it.readBytes() })
        return runFile(file, *args)
    }

    /** Runs the R script [file] with [args]; returns its standard output lines. Fails on a non-zero exit. */
    fun runFile(file: File, vararg args: String): List<String> {
        val rscript = assumeInstalled()
        val err = File(file.parentFile, "${file.name}.err")
        val process = ProcessBuilder(listOf(rscript.path, "--vanilla", file.path) + args).redirectError(err).start()
        val out = process.inputStream.bufferedReader().readLines()
        if (!process.waitFor(120, TimeUnit.SECONDS)) {
            process.destroyForcibly()
            fail("Rscript ${file.name} did not finish in 120 s")
        }
        assertEquals("Rscript ${file.name}: ${err.readText()}", 0, process.exitValue())
        return out
    }

    private fun find(): File? =
        (System.getenv("PATH").orEmpty().split(File.pathSeparator) + listOf("/usr/bin", "/usr/local/bin"))
            .map { File(it, "Rscript") }
            .firstOrNull { it.isFile && it.canExecute() }
}
