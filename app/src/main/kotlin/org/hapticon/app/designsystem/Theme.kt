package org.hapticon.app.designsystem

import android.os.Build
import androidx.compose.foundation.isSystemInDarkTheme
import androidx.compose.material3.ColorScheme
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.darkColorScheme
import androidx.compose.material3.dynamicDarkColorScheme
import androidx.compose.material3.dynamicLightColorScheme
import androidx.compose.material3.lightColorScheme
import androidx.compose.runtime.Composable
import androidx.compose.ui.graphics.Color
import androidx.compose.ui.platform.LocalContext
import com.materialkolor.dynamiccolor.DynamicColor
import com.materialkolor.dynamiccolor.MaterialDynamicColors
import com.materialkolor.hct.Hct
import com.materialkolor.scheme.DynamicScheme
import com.materialkolor.scheme.SchemeTonalSpot

/** Hapticon's one brand colour; every role of both schemes is derived from it. */
val HapticonSeed: Color = Color(0xFF5B4BC4)

/**
 * The Material 3 colour scheme derived from [seed] the way Material's own tools do it: the "tonal
 * spot" scheme of material-color-utilities (HCT colour space, tones chosen per role for contrast),
 * as ported to Kotlin by MaterialKolor. Same algorithm as Material Theme Builder, so no role is
 * picked by hand.
 */
fun seedColorScheme(seed: Color, dark: Boolean): ColorScheme {
    val scheme = SchemeTonalSpot(Hct.fromInt(seed.toArgbInt()), dark, 0.0)
    val roles = MaterialDynamicColors()
    fun DynamicColor.on(s: DynamicScheme) = Color(getArgb(s))
    val base = if (dark) darkColorScheme() else lightColorScheme()
    return base.copy(
        primary = roles.primary().on(scheme),
        onPrimary = roles.onPrimary().on(scheme),
        primaryContainer = roles.primaryContainer().on(scheme),
        onPrimaryContainer = roles.onPrimaryContainer().on(scheme),
        inversePrimary = roles.inversePrimary().on(scheme),
        secondary = roles.secondary().on(scheme),
        onSecondary = roles.onSecondary().on(scheme),
        secondaryContainer = roles.secondaryContainer().on(scheme),
        onSecondaryContainer = roles.onSecondaryContainer().on(scheme),
        tertiary = roles.tertiary().on(scheme),
        onTertiary = roles.onTertiary().on(scheme),
        tertiaryContainer = roles.tertiaryContainer().on(scheme),
        onTertiaryContainer = roles.onTertiaryContainer().on(scheme),
        background = roles.background().on(scheme),
        onBackground = roles.onBackground().on(scheme),
        surface = roles.surface().on(scheme),
        onSurface = roles.onSurface().on(scheme),
        surfaceVariant = roles.surfaceVariant().on(scheme),
        onSurfaceVariant = roles.onSurfaceVariant().on(scheme),
        surfaceTint = roles.surfaceTint().on(scheme),
        inverseSurface = roles.inverseSurface().on(scheme),
        inverseOnSurface = roles.inverseOnSurface().on(scheme),
        error = roles.error().on(scheme),
        onError = roles.onError().on(scheme),
        errorContainer = roles.errorContainer().on(scheme),
        onErrorContainer = roles.onErrorContainer().on(scheme),
        outline = roles.outline().on(scheme),
        outlineVariant = roles.outlineVariant().on(scheme),
        scrim = roles.scrim().on(scheme),
        surfaceBright = roles.surfaceBright().on(scheme),
        surfaceDim = roles.surfaceDim().on(scheme),
        surfaceContainer = roles.surfaceContainer().on(scheme),
        surfaceContainerHigh = roles.surfaceContainerHigh().on(scheme),
        surfaceContainerHighest = roles.surfaceContainerHighest().on(scheme),
        surfaceContainerLow = roles.surfaceContainerLow().on(scheme),
        surfaceContainerLowest = roles.surfaceContainerLowest().on(scheme),
    )
}

private fun Color.toArgbInt(): Int =
    ((alpha * 255 + 0.5f).toInt() shl 24) or ((red * 255 + 0.5f).toInt() shl 16) or
        ((green * 255 + 0.5f).toInt() shl 8) or (blue * 255 + 0.5f).toInt()

private val LightColors = seedColorScheme(HapticonSeed, dark = false)
private val DarkColors = seedColorScheme(HapticonSeed, dark = true)

/**
 * Material 3 theme: Hapticon's own light and dark schemes from [HapticonSeed]; with [dynamicColor]
 * (a setting, off by default) the wallpaper's colours on Android 12+. Dark follows the system.
 */
@Composable
fun HapticonTheme(
    darkTheme: Boolean = isSystemInDarkTheme(),
    dynamicColor: Boolean = false,
    content: @Composable () -> Unit,
) {
    val colors = when {
        dynamicColor && Build.VERSION.SDK_INT >= Build.VERSION_CODES.S -> {
            val context = LocalContext.current
            if (darkTheme) dynamicDarkColorScheme(context) else dynamicLightColorScheme(context)
        }
        darkTheme -> DarkColors
        else -> LightColors
    }
    MaterialTheme(colorScheme = colors, content = content)
}
