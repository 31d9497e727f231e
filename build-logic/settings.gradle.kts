// The build of the project's convention plugins (docs/build.md "Conventions"), included from the root
// settings.gradle.kts with pluginManagement { includeBuild("build-logic") }. It reads the project's one
// version catalog, so a convention names libraries and versions as the modules do.
dependencyResolutionManagement {
    repositories {
        google()
        mavenCentral()
    }
    versionCatalogs {
        create("libs") {
            from(files("../gradle/libs.versions.toml"))
        }
    }
}

rootProject.name = "build-logic"
