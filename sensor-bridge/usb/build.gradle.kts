// The Android side of sensor-bridge: USB host permission, attach/detach, and the adapter that
// gives the pure-Kotlin chip drivers a real UsbDeviceConnection. Nothing else lives here.
plugins {
    alias(libs.plugins.android.library)
}

android {
    namespace = "org.hapticon.sensor.usb"
    compileSdk = libs.versions.android.compileSdk.get().toInt()

    defaultConfig {
        minSdk = libs.versions.android.minSdk.get().toInt()
    }

    testOptions {
        targetSdk = libs.versions.android.targetSdk.get().toInt()
        unitTests.isIncludeAndroidResources = true
    }
}

dependencies {
    api(project(":sensor-bridge"))
    implementation(libs.androidx.core.ktx)
    implementation(libs.kotlinx.coroutines.android)

    testImplementation(project(":test-fixtures:android"))
    testImplementation(libs.junit4)
    testImplementation(libs.robolectric)
    testImplementation(libs.androidx.test.core)
    testImplementation(libs.kotlinx.coroutines.test)
}
