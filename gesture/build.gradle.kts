// Touch gestures, pure Kotlin: recordings, icon extraction (envelope fit) and live recognition (random forest).
plugins {
    // Model files are @Serializable documents (recognition/ModelDocuments.kt).
    alias(libs.plugins.hapticon.kotlin.library.serialization)
}

dependencies {
    api(project(":haptics-core"))

    testImplementation(project(":test-fixtures"))
    // WEKA, the EIT-skin paper's tool, as the oracle LogitBoost is tested against (GPL-3: tests only, never shipped).
    // Its netlib BLAS/LAPACK natives (via mtj and netlib-java) serve matrix classifiers, not LogitBoost or DecisionStump,
    // and their POMs name their group as ${project.parent.groupId}, which the offline build does not resolve.
    testImplementation(libs.weka.stable) { exclude(group = "com.github.fommil.netlib"); exclude(group = "com.googlecode.netlib-java") }
}
