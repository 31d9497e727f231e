package org.hapticon.companion.replicate

import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.UsageException


/**
 * `hapticon replicate ID`: runs the [Replication] with that id from [allReplications] and prints ours beside the
 * paper's figures; `hapticon replicate` alone lists them.
 */
fun runReplicate(args: List<String>, console: Console, replications: List<Replication> = allReplications) {
    if (args.isEmpty()) {
        for (r in replications) console.out.println("${r.id}  ${r.title}")
        return
    }
    if (args.size != 1 || args[0].startsWith("-")) throw UsageException("replicate takes one id: ${replications.joinToString("|") { it.id }}")
    val replication = replications.firstOrNull { it.id == args[0] }
        ?: throw UsageException("no replication '${args[0]}'; try ${replications.joinToString(", ") { it.id }}")
    console.out.println("${replication.id} ${replication.title}")
    replication.run(console.out)
}
