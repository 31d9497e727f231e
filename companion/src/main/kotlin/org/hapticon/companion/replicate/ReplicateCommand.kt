package org.hapticon.companion.replicate

import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.UsageException


/**
 * `hapticon replicate ID`: runs the [Replication] whose id (the paper's seed-file number) or one of whose short
 * [Replication.names] is ID, from [allReplications], and prints ours beside the paper's figures; `hapticon replicate`
 * alone lists them. Words after ID are that replication's [Replication.options].
 */
fun runReplicate(args: List<String>, console: Console, replications: List<Replication> = allReplications) {
    if (args.isEmpty()) {
        for (r in replications) console.out.println("${r.id}  ${r.title}${if (r.names.isEmpty()) "" else " (${r.names.joinToString(", ")})"}")
        return
    }
    val choices = replications.joinToString(", ") { (listOf(it.id) + it.names).joinToString("|") }
    if (args[0].startsWith("-")) throw UsageException("replicate takes one id or name first: $choices")
    val key = args[0].lowercase()
    val replication = replications.firstOrNull { it.id == key || key in it.names }
        ?: throw UsageException("no replication '${args[0]}'; try $choices")
    val options = args.drop(1)
    // Checked before the title is printed, so a usage error prints nothing else.
    replication.check(options)
    console.out.println("${replication.id} ${replication.title}")
    replication.run(console.out, options)
}
