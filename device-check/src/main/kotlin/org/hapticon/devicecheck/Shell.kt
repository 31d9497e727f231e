package org.hapticon.devicecheck

import android.app.UiAutomation
import android.os.ParcelFileDescriptor

/**
 * Shell commands as the `shell` user, through the instrumentation's UiAutomation: what `adb shell` may do (dumpsys,
 * `cmd notification`, `am`, `input`, `run-as` for a debuggable app), from inside the suite. The command line is split
 * at spaces, without quoting (UiAutomationConnection runs it with `Runtime.exec`), so no argument may contain one.
 */
class Shell(private val automation: UiAutomation) {
    /** Runs [command] and returns its standard output. */
    fun run(command: String): String =
        ParcelFileDescriptor.AutoCloseInputStream(automation.executeShellCommand(command)).use { it.readBytes().decodeToString() }

    /** Runs [command] with [input] on its standard input and returns its standard output (Android 12+). */
    fun run(command: String, input: String): String {
        val (output, stdin) = automation.executeShellCommandRw(command)
        ParcelFileDescriptor.AutoCloseOutputStream(stdin).use { it.write(input.encodeToByteArray()) }
        return ParcelFileDescriptor.AutoCloseInputStream(output).use { it.readBytes().decodeToString() }
    }
}
