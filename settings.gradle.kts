// Module list, read by Android Studio (Gradle) and by the offline build (./build).
pluginManagement {
    // The convention plugins (build-logic/src/main/kotlin/*.gradle.kts), read by ./build as well.
    includeBuild("build-logic")
    repositories {
        google()
        mavenCentral()
        gradlePluginPortal()
    }
}

dependencyResolutionManagement {
    repositoriesMode.set(RepositoriesMode.FAIL_ON_PROJECT_REPOS)
    repositories {
        google()
        mavenCentral()
    }
}

rootProject.name = "hapticon"

include(":haptics-core")
include(":sensor-bridge")
include(":sensor-bridge:usb")
include(":messaging")
include(":messaging:broker")
include(":study")
include(":gesture")
include(":test-fixtures")
include(":test-fixtures:android")
include(":companion")
include(":app")
include(":device-check")
include(":device-check:dumpsys")
