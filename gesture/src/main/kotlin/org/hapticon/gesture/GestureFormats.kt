package org.hapticon.gesture

/**
 * Every schema name and version of the gesture family, in one place: the gesture recogniser's model file
 * ([org.hapticon.gesture.recognition.GestureModel]) and the social-touch model
 * ([org.hapticon.gesture.social.SocialTouchModel]). The other families keep theirs in
 * `org.hapticon.core.io.HapticFormats`, `org.hapticon.messaging.WireFormats`, `org.hapticon.study.StudyFormats` and
 * `org.hapticon.sensor.SensorFormats`; docs/json.md lists them all.
 *
 * A version is what this build writes and the newest it reads; raising one is a format change that older builds
 * will refuse (docs/json.md, "Versions").
 */
public object GestureFormats {
    /** `schema` of a gesture model file. */
    public const val GESTURE_MODEL_SCHEMA: String = "hapticon.gesture-model"

    /** Version of the gesture model file. */
    public const val GESTURE_MODEL_VERSION: Int = 1

    /** `schema` of a social-touch model file. */
    public const val SOCIAL_TOUCH_MODEL_SCHEMA: String = "hapticon.social-touch-model"

    /** Version of the social-touch model file. */
    public const val SOCIAL_TOUCH_MODEL_VERSION: Int = 2
}
