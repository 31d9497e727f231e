package org.hapticon.testing

/**
 * A small long-format study results CSV (`src/main/resources/study/example-results.csv`): study
 * "demo-study", participants P01..P06, task "calm" (icons stroke, hug, knock; P06 has no hug rating) and
 * task "urgent" (knock, hit), one 1..5 rating per trial, questions quoted because they hold commas.
 */
public object StudyResults {
    /** The example's text. */
    public fun exampleCsv(): String =
        StudyResults::class.java.getResourceAsStream("/study/example-results.csv")!!.use { it.readBytes().toString(Charsets.UTF_8) }

    /** Ratings of the example by task and icon, in participant order (null: not rated). */
    public val EXAMPLE_RATINGS: Map<Pair<String, String>, List<Int?>> = linkedMapOf(
        ("calm" to "stroke") to listOf(4, 5, 4, 3, 5, 4),
        ("calm" to "hug") to listOf(5, 5, 4, 4, 5, null),
        ("calm" to "knock") to listOf(2, 1, 2, 3, 1, 2),
        ("urgent" to "knock") to listOf(5, 4, 4, 5, 3, 4),
        ("urgent" to "hit") to listOf(3, 2, 3, 2, 1, 2),
    )
}
