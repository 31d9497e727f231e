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
