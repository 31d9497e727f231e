// Chat messages with haptic icons over MQTT: the wire format and its hostile-input checks, flood
// control, outbox with retries, deduplication, and the MQTT messenger. Pure Kotlin/JVM so the app and
// the companion share it. The embedded broker lives in :messaging:broker and never reaches the app.
plugins {
    // The wire documents are @Serializable types (MessageCodec, docs/json.md).
    alias(libs.plugins.hapticon.kotlin.library.serialization)
}

dependencies {
    api(project(":haptics-core"))
    api(libs.kotlinx.coroutines.core)
    implementation(libs.hivemq.mqtt.client)
    implementation(libs.tink.android)

    testImplementation(project(":messaging:broker"))
    testImplementation(project(":test-fixtures"))
}
