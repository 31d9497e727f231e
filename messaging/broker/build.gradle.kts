// An embedded MQTT broker (HiveMQ Community Edition) for the companion's `hapticon broker`, the demo and
// the tests. A module of its own so that the broker and its server-side dependencies (RocksDB, Netty
// server, logback…) never reach the app, which depends on :messaging only.
plugins {
    alias(libs.plugins.hapticon.kotlin.library)
}

dependencies {
    implementation(libs.hivemq.community.edition.embedded)
    implementation(libs.logback.classic)
    implementation(libs.bouncycastle.bcpkix)
}
