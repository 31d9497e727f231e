// Shared test data of the Android modules' Robolectric tests (testImplementation of :app and :sensor-bridge:usb):
// real android.hardware.usb objects, which a plain-JVM module such as :test-fixtures cannot make. No main code
// depends on it (docs/architecture.md).
plugins {
    alias(libs.plugins.android.library)
}

android {
    namespace = "org.hapticon.testing.android"
    compileSdk = libs.versions.android.compileSdk.get().toInt()

    defaultConfig {
        minSdk = libs.versions.android.minSdk.get().toInt()
    }

    testOptions {
        targetSdk = libs.versions.android.targetSdk.get().toInt()
    }
}
