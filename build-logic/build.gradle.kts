// Precompiled script plugins: every src/main/kotlin/<id>.gradle.kts is the plugin <id>.
plugins {
    `kotlin-dsl`
}

dependencies {
    // compileOnly, as nowinandroid's build-logic does: at run time the conventions apply the Kotlin Gradle
    // plugin that the root build.gradle.kts loads (`apply false`), so every module shares that one copy.
    // Gradle generates the precompiled scripts' accessors (kotlin {}) from compileOnly plugins since 9.1.
    compileOnly(libs.kotlin.gradle.plugin)
    compileOnly(libs.kotlin.serialization.gradle.plugin)
}
