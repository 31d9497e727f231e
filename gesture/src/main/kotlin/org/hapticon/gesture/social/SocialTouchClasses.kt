package org.hapticon.gesture.social

/**
 * The classes and protocol counts of the EIT-skin social-touch paper (Silvera-Tawil, Rye & Velonaki, "Interpretation
 * of social touch on an artificial arm covered with an EIT-based sensitive skin", Int. J. Social Robotics 6(4):
 * 489–505, 2014), each cited as `SEEDFILE:LINE` of its text (`001_e790093bbd2e3cd3.txt`, docs/replication.md "001").
 *
 * Labels are plain strings, so a researcher trains and classifies under any other wording unchanged
 * (`hapticon train --classifier logitboost` takes whatever labels the files carry). Multi-word names are
 * hyphenated (`attention-getting`, `no-touch`) because a label is also a token of a `PERSON-LABEL-N.csv` file name.
 */
public object SocialTouchClasses {
    /** The six basic emotions, in the paper's order ("anger," "fear," "happiness," "sadness," "disgust" and "surprise": 001_e790093bbd2e3cd3.txt:146). */
    public val EMOTIONS: List<String> = listOf("anger", "fear", "happiness", "sadness", "disgust", "surprise")

    /** The six social messages, in the paper's order (001_e790093bbd2e3cd3.txt:152). */
    public val SOCIAL_MESSAGES: List<String> = listOf("attention-getting", "greeting", "acceptance", "rejection", "affection", "animosity")

    /** The "no touch" gesture, for touches too soft for the skin to detect (001_e790093bbd2e3cd3.txt:146, :152). */
    public const val NO_TOUCH: String = "no-touch"

    /** All thirteen classes a transmitter gave: the emotions, the social messages, then [NO_TOUCH]. */
    public val ALL: List<String> = EMOTIONS + SOCIAL_MESSAGES + NO_TOUCH

    /**
     * The emotion set as the paper classified it: the six emotions and no touch, 7 classes, chance one in seven
     * ("14 %", 001_e790093bbd2e3cd3.txt:214; Table 3's and Table 6's "Emotions" columns).
     */
    public val EMOTION_SET: List<String> = EMOTIONS + NO_TOUCH

    /** The social-message set: the six messages and no touch, 7 classes (Tables 3 and 6, "Messages"). */
    public val MESSAGE_SET: List<String> = SOCIAL_MESSAGES + NO_TOUCH

    /** Experiment 1: each word shown 50 times in random order, 650 touches per participant (001_e790093bbd2e3cd3.txt:164). */
    public const val EXPERIMENT_1_TAKES_PER_CLASS: Int = 50

    /** Experiment 1's transmitters: two, Participants A and B (001_e790093bbd2e3cd3.txt:160). */
    public const val EXPERIMENT_1_TRANSMITTERS: Int = 2

    /** Experiment 2: each word shown five times in random order, 2,730 touches over 42 participants (001_e790093bbd2e3cd3.txt:202). */
    public const val EXPERIMENT_2_TAKES_PER_CLASS: Int = 5

    /** Experiment 2's transmitters: 42, twenty-one pairs (001_e790093bbd2e3cd3.txt:198, :212). */
    public const val EXPERIMENT_2_TRANSMITTERS: Int = 42
}
