package org.hapticon.companion.replicate

import org.hapticon.gesture.social.LogitBoost
import org.hapticon.gesture.social.SocialTouchClasses
import org.hapticon.gesture.social.SocialTouchEvaluation
import org.hapticon.gesture.social.SocialTouchFeatures
import org.hapticon.gesture.social.SocialTouchSyntheticPeople
import java.io.PrintStream
import java.util.Locale

/**
 * 001: the EIT-skin paper's social-touch recognition — the 13 message features and LogitBoost over stumps, scored
 * the paper's way (10 × 10-fold cross-validation) and ours (leave one person out), on the six emotions, the six
 * social messages, and all thirteen classes with no touch. The paper's recordings are not published, so this runs
 * on [SocialTouchSyntheticPeople] ([people] people, [takesPerClass] messages per class each): the numbers show the
 * pipeline and how much pooling a person's messages into the training folds flatters, not the paper's skin.
 */
class SocialTouchReplication(private val people: Int = 8, private val takesPerClass: Int = 10, private val seed: Long = 1L) : Replication {
    override val id: String = "001"
    override val names: List<String> = listOf("eit-skin")
    override val title: String = "EIT-skin social touch: 13 features, LogitBoost, 10x10-fold CV vs leave-one-person-out"

    override fun run(out: PrintStream) {
        out.println()
        out.println("pipeline: ${SocialTouchFeatures.COUNT} features per message (${SocialTouchFeatures.NAMES.joinToString(" ")}),")
        out.println("          LogitBoost over regression stumps, ${LogitBoost.DEFAULT_ITERATIONS} rounds (Weka's default)")
        out.println("classes:  emotions ${SocialTouchClasses.EMOTIONS.joinToString(" ")};")
        out.println("          social messages ${SocialTouchClasses.SOCIAL_MESSAGES.joinToString(" ")}; and ${SocialTouchClasses.NO_TOUCH}")
        out.println("          (names as we recall the paper's lists: its text was searched for and not reached, so unverified; docs/replication.md)")
        out.println(
            "data:     $people simulated people x $takesPerClass messages per class, shuffled " +
                "(gesture SocialTouchSyntheticPeople; the paper's participants gave each class ${SocialTouchClasses.TAKES_PER_CLASS_IN_PAPER} times; its recordings are not published)",
        )
        out.println()
        out.println("                                   paper      ours 10x10 CV   ours LOPO")
        for ((what, labels) in listOf(
            "6 emotions" to SocialTouchClasses.EMOTIONS,
            "6 social messages" to SocialTouchClasses.SOCIAL_MESSAGES,
            "13 classes (incl. no touch)" to SocialTouchClasses.ALL,
        )) {
            val messages = SocialTouchSyntheticPeople.features(SocialTouchSyntheticPeople.messages(people, takesPerClass, seed, labels), labels)
            val cv = SocialTouchEvaluation.crossValidate(messages, seed = seed)
            val lopo = SocialTouchEvaluation.leaveOnePersonOut(messages)
            out.println(String.format(Locale.ROOT, "  %-30s %8s   %12.1f %%   %7.1f %%   (chance %.1f %%, %d messages)", what, "n/t", 100 * cv, 100 * lopo, 100.0 / labels.size, messages.size))
        }
        out.println()
        out.println("paper column: n/t = not transcribed. The paper reports LogitBoost accuracies 'comparable to those achieved by")
        out.println("humans' (its abstract); its per-set figures and Table 1 could not be reached, so none are printed.")
    }
}
