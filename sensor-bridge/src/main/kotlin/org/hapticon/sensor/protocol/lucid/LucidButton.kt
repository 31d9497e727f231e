package org.hapticon.sensor.protocol.lucid

/**
 * The presence-only flags of the LucidGloves alpha encoding: the letter appears in a line while the
 * button is pressed or the gesture is detected, and is absent otherwise. Letters as in the
 * LucidGloves firmware (`AlphaEncoding.cpp`) and the OpenGloves driver (`AlphaEncodingManager.cpp`).
 */
public enum class LucidButton(
    /** The letter that marks this flag in a line. */
    public val key: Char,
) {
    /** `H`: joystick pressed. */
    JOYSTICK_CLICK('H'),

    /** `I`: trigger button (the firmware sets it when the index curl passes its threshold). */
    TRIGGER('I'),

    /** `J`: A button. */
    A('J'),

    /** `K`: B button. */
    B('K'),

    /** `L`: grab gesture. */
    GRAB('L'),

    /** `M`: pinch gesture. */
    PINCH('M'),

    /** `N`: menu (system) button. */
    MENU('N'),

    /** `O`: calibration button. */
    CALIBRATE('O'),
}
