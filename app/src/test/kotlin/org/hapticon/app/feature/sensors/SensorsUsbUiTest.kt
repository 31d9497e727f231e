package org.hapticon.app.feature.sensors

import android.app.PendingIntent
import android.content.Intent
import android.content.pm.PackageManager
import android.hardware.usb.UsbDevice
import android.hardware.usb.UsbManager
import android.os.Looper
import androidx.compose.ui.test.SemanticsMatcher
import androidx.compose.ui.test.hasScrollToNodeAction
import androidx.compose.ui.test.hasText
import androidx.compose.ui.test.isSelected
import androidx.compose.ui.test.junit4.createEmptyComposeRule
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performScrollToNode
import androidx.test.core.app.ApplicationProvider
import androidx.test.platform.app.InstrumentationRegistry
import org.hapticon.app.di.AppContainer
import org.hapticon.app.HapticonApplication
import org.hapticon.app.MainActivity
import org.hapticon.sensor.usb.AndroidUsbDevices
import org.hapticon.testing.android.AndroidTestDevices
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.Robolectric
import org.robolectric.RobolectricTestRunner
import org.robolectric.android.controller.ActivityController
import org.robolectric.Shadows.shadowOf

/** Plugging a board in: the manifest, the intent reaching MainActivity, the device list, permission. */
@RunWith(RobolectricTestRunner::class)
class SensorsUsbUiTest {
    @get:Rule
    val rule = createEmptyComposeRule()

    private val app = ApplicationProvider.getApplicationContext<HapticonApplication>()
    private val usbManager = app.getSystemService(UsbManager::class.java)
    private val uno = AndroidTestDevices.arduinoUno(product = "Arduino Uno")
    private val asked = mutableListOf<PendingIntent>()
    private var activity: ActivityController<MainActivity>? = null

    @Before
    fun setUp() {
        shadowOf(app.packageManager).setSystemFeature(PackageManager.FEATURE_USB_HOST, true)
        // The real USB stack, with the permission dialog replaced by a recorder the test answers.
        app.container = AppContainer.create(app, usbDevices = AndroidUsbDevices(app, usbManager) { _, intent -> asked += intent })
    }

    @After
    fun tearDown() {
        activity?.pause()?.stop()?.destroy()
        app.container.sensorSession.disconnect()
    }

    private fun plugIn(device: UsbDevice) = shadowOf(usbManager).addOrUpdateUsbDevice(device, false)

    private fun launch(intent: Intent = Intent(app, MainActivity::class.java).setAction(Intent.ACTION_MAIN)) {
        // Robolectric's controller rather than ActivityScenario, whose close() deadlocks inside the compose rule here.
        activity = Robolectric.buildActivity(MainActivity::class.java, intent).setup()
        rule.waitForIdle()
    }

    private fun launchAttached(device: UsbDevice) = launch(
        Intent(app, MainActivity::class.java)
            .setAction(UsbManager.ACTION_USB_DEVICE_ATTACHED)
            .putExtra(UsbManager.EXTRA_DEVICE, device),
    )

    private fun scrollTo(matcher: SemanticsMatcher) {
        rule.onNode(hasScrollToNodeAction()).performScrollToNode(matcher)
    }

    @Test
    fun manifest_routesUsbAttachToMainActivityWithTheDeviceFilter() {
        val matches = app.packageManager.queryIntentActivities(
            Intent(UsbManager.ACTION_USB_DEVICE_ATTACHED).setPackage(app.packageName),
            PackageManager.GET_META_DATA,
        )

        val activity = matches.single().activityInfo
        assertEquals(MainActivity::class.java.name, activity.name)
        val info = app.packageManager.getActivityInfo(android.content.ComponentName(app, MainActivity::class.java), PackageManager.GET_META_DATA)
        assertEquals(org.hapticon.sensor.usb.R.xml.device_filter, info.metaData.getInt(UsbManager.ACTION_USB_DEVICE_ATTACHED))
    }

    @Test
    fun attachIntent_opensSensorsAndListsTheBoard() {
        plugIn(uno)

        launchAttached(uno)

        rule.onNode(hasText("Sensors") and isSelected()).assertExists()
        rule.onNodeWithText("Arduino Uno").assertExists()
        rule.onNodeWithText("CDC-ACM · 2341:0043").assertExists()
    }

    @Test
    fun attachIntent_whileRunning_arrivesAsNewIntentAndListsTheBoard() {
        launch()
        // The app opens on its chats.
        rule.onNode(hasText("Chats") and isSelected()).assertExists()

        plugIn(uno)
        // What the system does for a singleTop activity that is already on top.
        val attached = Intent(app, MainActivity::class.java)
            .setAction(UsbManager.ACTION_USB_DEVICE_ATTACHED)
            .putExtra(UsbManager.EXTRA_DEVICE, uno)
        InstrumentationRegistry.getInstrumentation().callActivityOnNewIntent(activity!!.get(), attached)
        rule.waitForIdle()

        rule.onNode(hasText("Sensors") and isSelected()).assertExists()
        rule.onNodeWithText("CDC-ACM · 2341:0043").assertExists()
    }

    @Test
    fun connect_userDeniesPermission_showsTheDenialClearly() {
        plugIn(uno)
        launchAttached(uno)

        scrollTo(hasText("Connect"))
        rule.onNodeWithText("Connect").performClick()
        rule.waitForIdle()
        assertEquals(1, asked.size)
        scrollTo(hasText("Waiting for USB permission", substring = true))
        rule.onNodeWithText("Waiting for USB permission for 2341:0043…").assertExists()

        // What the system does when the user taps "Cancel" in its dialog.
        val answer = Intent().putExtra(UsbManager.EXTRA_DEVICE, uno).putExtra(UsbManager.EXTRA_PERMISSION_GRANTED, false)
        asked.single().send(app, 0, answer)
        shadowOf(Looper.getMainLooper()).idle()
        rule.waitForIdle()

        scrollTo(hasText("USB permission denied", substring = true))
        rule.onNodeWithText("USB permission denied for 2341:0043", substring = true).assertExists()
        rule.onNodeWithText("tap Connect to ask again", substring = true).assertExists()
    }

    @Test
    fun noUsbHost_explainsInsteadOfListing() {
        shadowOf(app.packageManager).setSystemFeature(PackageManager.FEATURE_USB_HOST, false)
        plugIn(uno)

        launchAttached(uno)

        rule.onNodeWithText("This phone can't host USB devices").assertExists()
        rule.onNodeWithText("USB OTG", substring = true).assertExists()
        assertTrue(asked.isEmpty())
    }

    @Test
    fun noBoard_saysHowToConnectOne() {
        launch()

        rule.onNodeWithText("Sensors", useUnmergedTree = true).performClick()
        rule.waitForIdle()

        rule.onNodeWithText("No USB serial board plugged in", substring = true).assertExists()
        rule.onNodeWithText("Connect").assertExists()
    }

}
