package org.hapticon.study.schema

/**
 * A study protocol is invalid. [path] names the offending member as in the protocol JSON, for example
 * `tasks[1].stimuli[0].icon.attack` or `scale.points`; the message starts with it.
 */
public class ProtocolException(public val path: String, message: String) : IllegalArgumentException("$path: $message")
