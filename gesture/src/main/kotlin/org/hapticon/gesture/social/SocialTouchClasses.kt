package org.hapticon.gesture.social

/**
 * The class names of the EIT-skin social-touch paper (Silvera-Tawil, Rye & Velonaki, "Interpretation of social
 * touch on an artificial arm covered with an EIT-based sensitive skin", Int. J. Social Robotics 6(4):489–505,
 * 2014): six emotions and six social messages, each given by touching the arm, plus [NO_TOUCH].
 *
 * Provenance, stated plainly: the paper's abstract (checked) says it classified "six emotions and six social
 * messages" with LogitBoost; issue 15 adds "no touch" and that each class was given 50 times per participant in
 * random order. The twelve names below are the paper's lists as we recall them; the paper's full text was not
 * reachable when this was written, so they are **not re-checked against it** (docs/replication.md, 003). They are
 * plain strings, so a researcher with the paper's exact wording trains and classifies under that wording unchanged
 * (`hapticon train --classifier logitboost` takes whatever labels the files carry).
 */
public object SocialTouchClasses {
    /** The six emotions. */
    public val EMOTIONS: List<String> = listOf("anger", "disgust", "fear", "happiness", "sadness", "sympathy")

    /** The six social messages. */
    public val SOCIAL_MESSAGES: List<String> = listOf("acceptance", "affection", "animosity", "attention-getting", "greeting", "rejection")

    /** A message in which nothing touched the skin. */
    public const val NO_TOUCH: String = "no-touch"

    /** All thirteen classes: the emotions, the social messages, then [NO_TOUCH]. */
    public val ALL: List<String> = EMOTIONS + SOCIAL_MESSAGES + NO_TOUCH

    /** How many times the paper's participants gave each class, in random order (issue 15's summary of the paper). */
    public const val TAKES_PER_CLASS_IN_PAPER: Int = 50
}
