package org.hapticon.core.io

/**
 * Every schema name and version of the icon and pattern file family, in one place: Hapticon's own documents
 * ([IconJson], [org.hapticon.core.pattern.PatternJson]) and the two foreign pattern formats this build reads and
 * writes ([org.hapticon.core.pattern.Ahap], [org.hapticon.core.pattern.MetaHaptic]). The chat wire family
 * (which embeds icons and patterns) keeps its own in `org.hapticon.messaging.WireFormats`, the study family in
 * `org.hapticon.study.StudyFormats`, the gesture models in `org.hapticon.gesture.GestureFormats`, the
 * electrotactile calibration file in `org.hapticon.sensor.SensorFormats`; docs/json.md lists every family.
 *
 * A version is what this build writes and the newest it reads; raising one is a format change that older
 * builds will refuse (docs/json.md, "Versions").
 */
public object HapticFormats {
    /** `schema` of an icon document. */
    public const val ICON_SCHEMA: String = "hapticon.icon"

    /** Version of the icon document. */
    public const val ICON_VERSION: Int = 1

    /** `schema` of a pattern document. */
    public const val PATTERN_SCHEMA: String = "hapticon.pattern"

    /** Version of the pattern document. */
    public const val PATTERN_VERSION: Int = 1

    /** The AHAP `Version` written (Apple's format version 1.0; reading does not require the member). */
    public const val AHAP_VERSION: Int = 1

    /** The Meta `.haptic` data-model major version read and written (Lofelt/NiceVibrations `core/datamodel/src/v1.rs`). */
    public const val HAPTIC_MAJOR_VERSION: Int = 1
}
