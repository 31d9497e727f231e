package org.hapticon.app

import android.app.Application
import org.hapticon.app.data.IconRepository
import org.hapticon.app.data.PresetIconRepository
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.app.playback.VibratorHapticPlayer

/** Holds the app's long-lived objects; tests replace them through [container]. */
class HapticonApplication : Application() {
    lateinit var container: AppContainer

    override fun onCreate() {
        super.onCreate()
        container = AppContainer(
            iconRepository = PresetIconRepository(),
            player = VibratorHapticPlayer.create(this),
        )
    }
}

/** The app's dependencies, built once per process (manual injection: small app, no framework). */
data class AppContainer(
    val iconRepository: IconRepository,
    val player: HapticPlayer,
)
