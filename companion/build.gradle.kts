plugins {
    alias(libs.plugins.kotlin.jvm)
    // The bench reports are @Serializable documents (BenchDocument, LoadDocument; docs/json.md).
    alias(libs.plugins.kotlin.serialization)
    application
}

application {
    mainClass = "org.hapticon.companion.MainKt"
}

kotlin {
    jvmToolchain(libs.versions.jvmTarget.get().toInt())
}

dependencies {
    implementation(project(":haptics-core"))
    implementation(project(":sensor-bridge"))
    implementation(project(":messaging"))
    implementation(project(":messaging:broker"))
    implementation(project(":study"))
    implementation(project(":gesture"))
    implementation(libs.kotlinx.serialization.json)
    implementation(libs.sqlite.jdbc) // the study collector's default store
    implementation(libs.postgresql) // the study collector's optional store
    implementation(libs.jetty.server) // the study collector's HTTP server
    implementation(libs.commons.csv) // bench --analysis only: the baseline our CSV reader is measured against
    implementation(libs.jserialcomm) // `hapticon board`: the desktop's serial ports (the app has its own USB drivers)
    implementation(libs.logback.classic) // to quiet Jetty's INFO lines (HiveMQ's logback.xml prints them to stdout)

    testImplementation(project(":test-fixtures"))
    testImplementation(libs.junit4)
    testImplementation(libs.hivemq.mqtt.client) // a raw client for hostile payloads in the chat tests
}
