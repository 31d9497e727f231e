package org.hapticon.companion.replicate

/** Every replication `hapticon replicate` knows, by id. */
val allReplications: List<Replication> = listOf(
    HapticIconsReplication,
)
