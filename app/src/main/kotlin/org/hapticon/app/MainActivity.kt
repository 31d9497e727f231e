package org.hapticon.app

import android.os.Bundle
import androidx.activity.ComponentActivity
import androidx.activity.compose.setContent
import androidx.activity.enableEdgeToEdge
import org.hapticon.app.designsystem.HapticonTheme
import org.hapticon.app.feature.icons.IconsRoute

/** The single activity: hosts the Compose UI. */
class MainActivity : ComponentActivity() {
    override fun onCreate(savedInstanceState: Bundle?) {
        super.onCreate(savedInstanceState)
        enableEdgeToEdge()
        val container = (application as HapticonApplication).container
        setContent {
            HapticonTheme {
                IconsRoute(container)
            }
        }
    }
}
