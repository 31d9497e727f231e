package org.hapticon.companion.replicate

/** One published result reproduced by `hapticon replicate ID`. */ interface Replication { val id: String; val title: String; fun run(out: java.io.PrintStream) }
