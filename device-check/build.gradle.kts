// The device check (docs/device-check.md): an instrumentation APK that drives the debug app on a real phone
// (`./build device-check`) and checks what Robolectric cannot: what Android does to a haptic message that
// arrives with the app swiped away, the screen off or Do Not Disturb on.
//
// A test module of its own, not the app's androidTest: its instrumentation targets its own package, so the
// suite runs in a process and uid of its own (AGP's self-instrumenting test, as macrobenchmark's). An
// instrumented process is held at PROCESS_STATE_FOREGROUND_SERVICE (OomAdjuster, "instrumentation"), which
// VibrationSettings counts as foreground for the whole uid: a suite inside the app's uid would make every
// background vibration pass and could never see the rule it is here to check.
plugins {
    alias(libs.plugins.android.test)
}

android {
    namespace = "org.hapticon.devicecheck"
    compileSdk = libs.versions.android.compileSdk.get().toInt()
    targetProjectPath = ":app"

    defaultConfig {
        // Android 12: UiAutomation.executeShellCommandRw (stdin for run-as) and dumpsys vibrator_manager.
        minSdk = 31
        targetSdk = libs.versions.android.targetSdk.get().toInt()
        testInstrumentationRunner = "androidx.test.runner.AndroidJUnitRunner"
    }

    experimentalProperties["android.experimental.self-instrumenting"] = true
}

dependencies {
    // The peer: the app's own messaging (wire format, receipts) over the same HiveMQ client.
    implementation(project(":messaging"))
    // The knock's waveform as the app renders it, to compare with what the vibrator was given.
    implementation(project(":haptics-core"))
    // What the suite reads in Android's dumps, parsed in plain Kotlin and tested on the JVM.
    implementation(project(":device-check:dumpsys"))
    implementation(libs.androidx.test.runner)
    implementation(libs.androidx.test.ext.junit)
    implementation(libs.androidx.test.uiautomator)
    implementation(libs.junit4)
}
