plugins {
    alias(libs.plugins.android.application)
    alias(libs.plugins.kotlin.compose)
    alias(libs.plugins.ksp)
}

android {
    namespace = "org.hapticon.app"
    compileSdk = libs.versions.android.compileSdk.get().toInt()

    defaultConfig {
        applicationId = "org.hapticon.app"
        minSdk = libs.versions.android.minSdk.get().toInt()
        targetSdk = libs.versions.android.targetSdk.get().toInt()
        versionCode = 1
        versionName = "0.1.0"
    }

    testOptions {
        unitTests.isIncludeAndroidResources = true
    }
}

// Room: the schema JSON of every version is committed under app/schemas (migration tests read it).
ksp {
    arg("room.schemaLocation", "$projectDir/schemas")
    arg("room.generateKotlin", "true")
}

dependencies {
    implementation(project(":haptics-core"))
    implementation(project(":sensor-bridge:usb"))
    implementation(project(":messaging"))
    implementation(project(":study"))
    implementation(project(":gesture"))
    implementation(libs.androidx.room.runtime)
    implementation(libs.androidx.room.ktx)
    ksp(libs.androidx.room.compiler)
    implementation(platform(libs.androidx.compose.bom))
    implementation(libs.androidx.core.ktx)
    implementation(libs.androidx.activity.compose)
    implementation(libs.androidx.lifecycle.runtime.compose)
    implementation(libs.androidx.lifecycle.viewmodel.compose)
    implementation(libs.androidx.compose.ui)
    implementation(libs.androidx.compose.foundation)
    implementation(libs.androidx.compose.material3)
    implementation(libs.kotlinx.coroutines.android)
    implementation(libs.androidx.media3.exoplayer)
    implementation(libs.material.color.utilities)
    implementation(libs.zxing.core)
    // The broker password and the end-to-end keys are wrapped by an AES key in Android Keystore (Tink).
    implementation(libs.tink.android)

    testImplementation(project(":test-fixtures"))
    testImplementation(project(":test-fixtures:android"))
    // The embedded broker: "Stay reachable" is tested end to end over real MQTT.
    testImplementation(project(":messaging:broker"))
    // A bare MQTT client: the tests publish what a hostile participant or the broker's operator would (a flood, a
    // recorded payload replayed byte for byte), which the app's messenger never sends.
    testImplementation(libs.hivemq.mqtt.client)
    testImplementation(libs.junit4)
    testImplementation(libs.robolectric)
    testImplementation(libs.androidx.test.core)
    testImplementation(libs.androidx.test.ext.junit)
    testImplementation(libs.androidx.compose.ui.test.junit4)
    testImplementation(libs.kotlinx.coroutines.test)
    testImplementation(libs.roborazzi)
    testImplementation(libs.roborazzi.compose)
    // ATF 3.1 also asks for Material Components 1.2.0-rc01, which is only on Google's repository and which
    // the checks we run never load.
    testImplementation(libs.accessibility.test.framework) { exclude(group = "com.google.android.material") }
    debugImplementation(libs.androidx.compose.ui.test.manifest)
}
