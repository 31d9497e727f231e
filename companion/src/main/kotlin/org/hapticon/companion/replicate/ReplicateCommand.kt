package org.hapticon.companion.replicate

import org.hapticon.companion.Arguments
import org.hapticon.companion.Console
import org.hapticon.companion.UsageException

/** `hapticon replicate ID`: runs the replication [ID] of [allReplications]; without an id, lists them. */
fun runReplicate(args: List<String>, console: Console) {
    val arguments = Arguments.parse("replicate", args)
    val ids = arguments.positionals
    if (ids.isEmpty()) {
        for (replication in allReplications) console.out.println("${replication.id}  ${replication.title}")
        return
    }
    if (ids.size > 1) throw UsageException("replicate takes one id, got ${ids.size}")
    val replication = allReplications.firstOrNull { it.id == ids.single() }
        ?: throw UsageException("no replication '${ids.single().take(40)}'; known: ${allReplications.joinToString(", ") { it.id }}")
    replication.run(console.out)
}
