package org.hapticon.companion.cli

/**
 * A mistake the user can fix (bad command line, missing or invalid input, unwritable output). `runCli`
 * prints its one-line [message] and exits with `EXIT_USAGE`; no stack trace.
 */
class UsageException(message: String) : Exception(message)
