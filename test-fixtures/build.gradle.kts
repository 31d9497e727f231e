// Shared test doubles and recorded data, used only by the tests of every other module (testImplementation):
// no main code depends on it (docs/architecture.md), and it hands JUnit to nobody.
plugins {
    alias(libs.plugins.kotlin.jvm)
}

kotlin {
    jvmToolchain(libs.versions.jvmTarget.get().toInt())
}

dependencies {
    api(project(":haptics-core"))
    api(project(":sensor-bridge")) // TestUsbDevices: the USB device list double of the live session
    api(project(":messaging")) // TestKeyPins: end-to-end key pins in memory

    testImplementation(libs.junit4)
}
