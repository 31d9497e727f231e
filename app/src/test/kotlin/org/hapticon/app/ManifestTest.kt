package org.hapticon.app

import android.content.Context
import android.content.pm.PackageManager
import androidx.test.core.app.ApplicationProvider
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

@RunWith(RobolectricTestRunner::class)
class ManifestTest {
    @Test
    fun mergedManifest_requestsVibrateAndInternet() {
        val context = ApplicationProvider.getApplicationContext<Context>()
        val info = context.packageManager.getPackageInfo(context.packageName, PackageManager.GET_PERMISSIONS)
        val requested = info.requestedPermissions.orEmpty().toSet()
        assertTrue(requested.toString(), "android.permission.VIBRATE" in requested)
        assertTrue(requested.toString(), "android.permission.INTERNET" in requested)
    }

    @Test
    fun mergedManifest_stayReachableServiceHasItsTypeAndPermissions() {
        val context = ApplicationProvider.getApplicationContext<Context>()
        val info = context.packageManager.getPackageInfo(context.packageName, PackageManager.GET_PERMISSIONS or PackageManager.GET_SERVICES)
        val requested = info.requestedPermissions.orEmpty().toSet()
        for (p in listOf("FOREGROUND_SERVICE", "FOREGROUND_SERVICE_REMOTE_MESSAGING", "RECEIVE_BOOT_COMPLETED", "POST_NOTIFICATIONS")) {
            assertTrue(requested.toString(), "android.permission.$p" in requested)
        }
        val service = info.services.orEmpty().single { it.name == "org.hapticon.app.sync.ReachableService" }
        assertEquals(android.content.pm.ServiceInfo.FOREGROUND_SERVICE_TYPE_REMOTE_MESSAGING, service.foregroundServiceType)
        assertEquals(false, service.exported)
        // Android 15 forbids BOOT_COMPLETED receivers to start these types (developer.android.com/about/versions/15/
        // changes/foreground-service-types; microphone since 14); the boot path starts remoteMessaging.
        val notFromBoot = android.content.pm.ServiceInfo.FOREGROUND_SERVICE_TYPE_DATA_SYNC or android.content.pm.ServiceInfo.FOREGROUND_SERVICE_TYPE_CAMERA or
            android.content.pm.ServiceInfo.FOREGROUND_SERVICE_TYPE_MEDIA_PLAYBACK or android.content.pm.ServiceInfo.FOREGROUND_SERVICE_TYPE_PHONE_CALL or
            android.content.pm.ServiceInfo.FOREGROUND_SERVICE_TYPE_MEDIA_PROJECTION or android.content.pm.ServiceInfo.FOREGROUND_SERVICE_TYPE_MICROPHONE
        assertEquals(0, service.foregroundServiceType and notFromBoot)
        // The battery exemption is asked with Android's dialog, which needs this normal permission.
        assertTrue(requested.toString(), "android.permission.REQUEST_IGNORE_BATTERY_OPTIMIZATIONS" in requested)
        // The camera app takes an invite's photo: Hapticon itself asks for no camera (declaring it would make
        // ACTION_IMAGE_CAPTURE need the permission granted).
        assertEquals(false, "android.permission.CAMERA" in requested)
    }

    @Test
    fun launcherIcon_isTheAdaptiveIconWithAMonochromeLayer() {
        val context = ApplicationProvider.getApplicationContext<Context>()
        val info = context.packageManager.getApplicationInfo(context.packageName, 0)
        assertEquals(R.mipmap.ic_launcher, info.icon)
        val icon = context.getDrawable(info.icon) as android.graphics.drawable.AdaptiveIconDrawable
        assertTrue(icon.foreground != null && icon.background != null)
        assertTrue("themed icons need the monochrome layer", icon.monochrome != null)
        val launcher = context.packageManager.queryIntentActivities(
            android.content.Intent(android.content.Intent.ACTION_MAIN).addCategory(android.content.Intent.CATEGORY_LAUNCHER).setPackage(context.packageName), 0,
        ).single()
        assertEquals(R.mipmap.ic_launcher, launcher.iconResource.takeIf { it != 0 } ?: info.icon)
    }

    @Test
    fun inviteLink_opensTheMainActivity() {
        val context = ApplicationProvider.getApplicationContext<Context>()
        val view = android.content.Intent(android.content.Intent.ACTION_VIEW, android.net.Uri.parse("hapticon://invite?user=bob&broker=10.0.0.2"))
            .addCategory(android.content.Intent.CATEGORY_BROWSABLE)
        val handlers = context.packageManager.queryIntentActivities(view, 0)
        assertEquals(listOf("org.hapticon.app.MainActivity"), handlers.map { it.activityInfo.name })
    }
}
