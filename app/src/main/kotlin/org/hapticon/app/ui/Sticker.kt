package org.hapticon.app.ui

import androidx.annotation.DrawableRes
import org.hapticon.app.R

/** The bundled stickers: our own vector drawables; [wireName] is what travels in a message. */
enum class Sticker(val wireName: String, val label: String, @DrawableRes val drawable: Int) {
    STROKE("stroke", "Stroke", R.drawable.sticker_stroke),
    HIT("hit", "Hit", R.drawable.sticker_hit),
    KNOCK("knock", "Knock", R.drawable.sticker_knock),
    HUG("hug", "Hug", R.drawable.sticker_hug),
    SMILE("smile", "Smile", R.drawable.sticker_smile),
    HEART("heart", "Heart", R.drawable.sticker_heart),
    WAVE("wave", "Wave", R.drawable.sticker_wave),
    ;

    companion object {
        /** The sticker for a received name, or null for one this build does not have (shown as its name). */
        fun of(wireName: String?): Sticker? = entries.firstOrNull { it.wireName == wireName }
    }
}
