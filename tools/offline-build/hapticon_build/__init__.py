"""Offline build for Hapticon: drives kotlinc, aapt2, D8 and apksig directly from the Gradle files.

Gradle cannot run on our machines; this package reads the same `settings.gradle.kts`,
per-module `build.gradle.kts` and `gradle/libs.versions.toml` that Android Studio reads, so the
two builds cannot drift. It understands a deliberately small declarative subset of the Gradle
Kotlin DSL and fails loudly on anything else.
"""
