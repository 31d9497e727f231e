package org.hapticon.companion.cli

/**
 * The arguments of one command, checked against the options it accepts: `--name VALUE` or `--name=VALUE`
 * for value options, a bare `--name` for flags; anything else not starting with `-` is positional.
 * Every problem is a [UsageException] naming the option.
 */
class Arguments private constructor(
    private val command: String,
    /** Positional arguments in order. */
    val positionals: List<String>,
    private val values: Map<String, String>,
    private val flags: Set<String>,
) {
    /** True when flag `--[name]` was given. */
    fun flag(name: String): Boolean = name in flags

    /** The value of `--[name]`, or null when it was not given. */
    fun value(name: String): String? = values[name]

    /** The value of `--[name]`; a [UsageException] when it was not given. */
    fun required(name: String): String = values[name] ?: throw UsageException("$command needs --$name")

    /** `--[name]` as a whole number, or [default] when not given. */
    fun int(name: String, default: Int): Int {
        val text = values[name] ?: return default
        return text.toIntOrNull() ?: throw UsageException("--$name must be a whole number, got '$text'")
    }

    /** `--[name]` looked up (case-insensitively) in [choices], or [default] when not given. */
    fun <T> choice(name: String, choices: Map<String, T>, default: T): T {
        val text = values[name] ?: return default
        return choices[text.lowercase()]
            ?: throw UsageException("--$name must be ${choices.keys.joinToString(" or ")}, got '$text'")
    }

    /** The one positional argument, described as [what] in errors when it is missing or not alone. */
    fun single(what: String): String {
        if (positionals.isEmpty()) throw UsageException("$command needs $what")
        if (positionals.size > 1) throw UsageException("unexpected argument '${positionals[1]}' for $command")
        return positionals[0]
    }

    /** Fails when any positional argument was given. */
    fun requireNoPositionals() {
        if (positionals.isNotEmpty()) throw UsageException("unexpected argument '${positionals[0]}' for $command")
    }

    companion object {
        /** Parses [args] of [command], which accepts value options [valueOptions] and [flagOptions] (names without `--`). */
        fun parse(
            command: String,
            args: List<String>,
            valueOptions: Set<String> = emptySet(),
            flagOptions: Set<String> = emptySet(),
        ): Arguments {
            val positionals = ArrayList<String>()
            val values = LinkedHashMap<String, String>()
            val flags = LinkedHashSet<String>()
            var i = 0
            while (i < args.size) {
                val arg = args[i++]
                if (!arg.startsWith("-") || arg == "-") {
                    positionals += arg
                    continue
                }
                if (!arg.startsWith("--")) throw UsageException("unknown option $arg for $command")
                val name = arg.removePrefix("--").substringBefore('=')
                val inline = if ('=' in arg) arg.substringAfter('=') else null
                when (name) {
                    in flagOptions -> {
                        if (inline != null) throw UsageException("--$name takes no value")
                        if (!flags.add(name)) throw UsageException("--$name given twice")
                    }
                    in valueOptions -> {
                        // A following option is not a value: `--out --rate 8000` forgot the file name.
                        val value = inline ?: args.getOrNull(i)?.takeUnless { it.startsWith("--") }?.also { i++ }
                        if (value.isNullOrEmpty()) throw UsageException("--$name needs a value")
                        if (values.put(name, value) != null) throw UsageException("--$name given twice")
                    }
                    else -> throw UsageException("unknown option --$name for $command")
                }
            }
            return Arguments(command, positionals, values, flags)
        }
    }
}
