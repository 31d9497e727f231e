package org.hapticon.sensor

/**
 * Every schema name and version of the sensor family, in one place: the electrotactile calibration file
 * ([org.hapticon.sensor.electrotactile.CalibrationFile]). The other families keep theirs in
 * `org.hapticon.core.io.HapticFormats`, `org.hapticon.messaging.WireFormats`, `org.hapticon.study.StudyFormats` and
 * `org.hapticon.gesture.GestureFormats`; docs/json.md lists them all.
 *
 * A version is what this build writes and the newest it reads; raising one is a format change that older builds
 * will refuse (docs/json.md, "Versions").
 */
public object SensorFormats {
    /** `schema` of an electrotactile calibration file (one person's calibrated step per electrode). */
    public const val CALIBRATION_SCHEMA: String = "hapticon.electrotactile-calibration"

    /** Version of the electrotactile calibration file. */
    public const val CALIBRATION_VERSION: Int = 1
}
