// Module list, read by Android Studio (Gradle) and by the offline build (./build).
pluginManagement {
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
include(":companion")
include(":app")
