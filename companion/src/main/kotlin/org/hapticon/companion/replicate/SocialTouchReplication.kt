package org.hapticon.companion.replicate

import org.hapticon.gesture.social.LogitBoost
import org.hapticon.gesture.social.SocialTouchClasses
import org.hapticon.gesture.social.SocialTouchEvaluation
import org.hapticon.gesture.social.SocialTouchFeatures
import org.hapticon.gesture.social.SocialTouchMessage
import org.hapticon.gesture.social.SocialTouchSyntheticPeople
import org.hapticon.gesture.social.TouchMessages
import java.io.PrintStream
import java.util.Locale

/**
 * 001: the EIT-skin social-touch paper (Silvera-Tawil, Rye & Velonaki 2014, `001_e790093bbd2e3cd3.txt`): its published
 * accuracies, each with its line, then the same evaluations run on [SocialTouchSyntheticPeople] following its two
 * protocols — in a table of their own, labelled simulated and not comparable, because the paper's recordings are not
 * published. [experiment1] and [experiment2] give the simulated sessions (smaller ones in tests).
 */
class SocialTouchReplication(
    private val experiment1: () -> List<SocialTouchMessage> = { SocialTouchSyntheticPeople.experiment1() },
    private val experiment2: () -> List<SocialTouchMessage> = { SocialTouchSyntheticPeople.experiment2() },
    private val runs: Int = 10,
) : Replication {
    override val id: String = "001"
    override val names: List<String> = listOf("eit-skin")
    override val title: String = "EIT-skin social touch: Table 1's 13 features, WEKA's LogitBoost, Experiments 1 and 2"

    override fun run(out: PrintStream) {
        val s = LogitBoost.WEKA_DEFAULTS
        out.println()
        out.println("Source: Silvera-Tawil, Rye & Velonaki, Int. J. Social Robotics 6(4):489-505, 2014 (lines of 001_e790093bbd2e3cd3.txt).")
        out.println("classes:  emotions ${SocialTouchClasses.EMOTIONS.joinToString(" ")} (:146);")
        out.println("          social messages ${SocialTouchClasses.SOCIAL_MESSAGES.joinToString(" ")} (:152);")
        out.println("          each set with ${SocialTouchClasses.NO_TOUCH}: 7 classes, chance 1 in 7 = 14 % (:214)")
        out.println("features: Table 1 (:111-124) ${SocialTouchFeatures.NAMES.joinToString(" ")}")
        out.println("          per touch, averaged over a message's touches (:132); touches cut at a threshold on skin or joint (:101)")
        out.println(
            "model:    WEKA LogitBoost over DecisionStump (:136, :138), WEKA's defaults (paper silent): " +
                "${s.iterations} rounds, shrinkage ${fmt(s.shrinkage)}, Z max ${fmt(s.zMax)}, weight threshold ${s.weightThresholdPercent} %",
        )
        out.println()
        out.println("The paper's figures: % correct, mean (SD)          emotions      messages      cited")
        out.println("Experiment 1: one transmitter, ten 10-fold CVs (:166), 650 touches each (:164)")
        paper(out, "  Participant A, LogitBoost (Table 3)", "94.3 (3.8)", "94.7 (3.5)", ":181")
        paper(out, "  Participant B, LogitBoost (Table 3)", "81.7 (6.3)", "73.7 (5.8)", ":182")
        paper(out, "  trained on A tested on B and back (Table 4)", "32", "51", ":176")
        out.println("Experiment 2: 42 transmitters, each left out in turn (:212), 2,730 touches (:202)")
        paper(out, "  LogitBoost (Table 6)", "46.9 (11.4)", "49.7 (13.8)", ":221")
        paper(out, "  human recipients (Table 6)", "51.8 (16.0)", "62.1 (16.5)", ":222")
        out.println("  (humans: 40 recipients, the mixed-gender couple left out (:198); no \"no touch\" and a \"none\" option (:204))")
        out.println()

        out.println("Ours: simulated, not comparable (SocialTouchSyntheticPeople; the paper's recordings are not published)")
        val one = features(experiment1())
        val people1 = one.people.distinct()
        out.println("Experiment 1 protocol: ${people1.size} simulated transmitters x 13 classes, ${one.size / maxOf(1, people1.size)} messages each; $runs runs of 10-fold CV, SD over the folds")
        val sets = listOf(SocialTouchClasses.EMOTION_SET, SocialTouchClasses.MESSAGE_SET).map { set -> set.map { SocialTouchClasses.ALL.indexOf(it) } }
        for (person in people1) {
            val cells = sets.map { set -> SocialTouchEvaluation.crossValidate(one.select(set).of(person), runs = runs).let { cell(it.mean, it.sd) } }
            ours(out, "  simulated $person, LogitBoost", cells)
        }
        if (people1.size == 2) {
            val cells = sets.map { set ->
                val a = one.select(set).of(people1[0])
                val b = one.select(set).of(people1[1])
                String.format(Locale.ROOT, "%.0f", 50 * (SocialTouchEvaluation.trainTest(a, b) + SocialTouchEvaluation.trainTest(b, a)))
            }
            ours(out, "  trained on ${people1[0]} tested on ${people1[1]} and back", cells)
        }
        val two = features(experiment2())
        val people2 = two.people.distinct().size
        out.println("Experiment 2 protocol: $people2 simulated transmitters x 13 classes, ${two.size / maxOf(1, people2)} messages each; each left out in turn, SD over transmitters")
        ours(out, "  LogitBoost", sets.map { set -> SocialTouchEvaluation.leaveOneTransmitterOut(two.select(set)).let { cell(it.mean, it.sd) } })
        ours(out, "  human recipients", listOf("-", "-"))
        out.println("  (no simulated human recipients: a person's judgement is not something these prototypes can stand in for)")
        out.println()
        out.println("The simulated figures say how separable our prototypes are (their numbers are ours, docs/replication.md \"001\"),")
        out.println("and how much scoring one transmitter's own touches (Experiment 1) flatters against an unseen transmitter (Experiment 2).")
    }

    private fun features(messages: List<SocialTouchMessage>): TouchMessages = SocialTouchSyntheticPeople.features(messages, SocialTouchClasses.ALL)

    private fun paper(out: PrintStream, what: String, emotions: String, messages: String, line: String) =
        out.println(String.format(Locale.ROOT, "%-50s %-13s %-13s %s", what, emotions, messages, line))

    private fun ours(out: PrintStream, what: String, cells: List<String>) =
        out.println(String.format(Locale.ROOT, "%-50s %-13s %s", what, cells[0], cells[1]))

    private fun cell(mean: Double, sd: Double) = String.format(Locale.ROOT, "%.1f (%.1f)", 100 * mean, 100 * sd)

    private fun fmt(v: Double) = if (v == Math.rint(v)) "%.0f".format(Locale.ROOT, v) else v.toString()
}
