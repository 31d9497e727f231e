"""Tests of the offline build's own logic: the Gradle-file reader and Gradle-semantics resolution."""
import json
import os
import subprocess
import tempfile
import textwrap
import unittest
from unittest import mock

from hapticon_build.android import (REFLECTIVE_CLASSES, REFLECTIVE_MEMBERS, DexClass, Signing, dex_classes,
                                    dex_code_strings, dex_field_lookups, excluded, field_lookups, read_field_mapping, read_mapping,
                                    required_classes, required_members, smoke_check)
from hapticon_build.errors import BuildError
from hapticon_build.kotlin import compiler_arguments
from hapticon_build.maven import Repository
from hapticon_build.project import SERIALIZATION_PLUGIN as SERIALIZATION, Catalog, load_project
from hapticon_build.resolver import Resolver, concrete_version, highest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))

CATALOG = """
[versions]
kotlin = "2.4.21"
android-minSdk = "26"
[libraries]
kotlin-stdlib = { module = "org.jetbrains.kotlin:kotlin-stdlib", version.ref = "kotlin" }
androidx-compose-ui = { module = "androidx.compose.ui:ui" }
junit4 = "junit:junit:4.13.2"
[plugins]
kotlin-jvm = { id = "org.jetbrains.kotlin.jvm", version.ref = "kotlin" }
android-application = { id = "com.android.application", version = "9.4.1" }
kotlin-compose = { id = "org.jetbrains.kotlin.plugin.compose", version.ref = "kotlin" }
kotlin-serialization = { id = "org.jetbrains.kotlin.plugin.serialization", version.ref = "kotlin" }
"""


def write(root, path, text):
    full = os.path.join(root, path)
    os.makedirs(os.path.dirname(full), exist_ok=True)
    with open(full, "w") as f:
        f.write(textwrap.dedent(text))


class ProjectReaderTest(unittest.TestCase):
    def setUp(self):
        self.root = tempfile.mkdtemp()
        write(self.root, "gradle/libs.versions.toml", CATALOG)
        write(self.root, "settings.gradle.kts", 'rootProject.name = "demo"\ninclude(":core")\ninclude(":app")\n')
        write(self.root, "core/build.gradle.kts", """
            plugins {
                alias(libs.plugins.kotlin.jvm)
            }
            kotlin { explicitApi() }
            dependencies {
                testImplementation(libs.junit4)
            }
        """)

    def app(self, dependencies):
        write(self.root, "app/build.gradle.kts", """
            plugins {
                alias(libs.plugins.android.application)
            }
            android {
                namespace = "org.demo"
                compileSdk = 37
                defaultConfig {
                    minSdk = libs.versions.android.minSdk.get().toInt()
                    targetSdk = 35
                }
            }
            dependencies {
        """ + dependencies + "\n}\n")

    def test_load_project_readsModulesPluginsAndDependencies(self):
        self.app('    implementation(project(":core"))\n    implementation(libs.androidx.compose.ui)')
        project = load_project(self.root)
        self.assertEqual([":core", ":app"], list(project.modules))
        core, app = project.module(":core"), project.module(":app")
        self.assertTrue(core.explicit_api)
        self.assertEqual({"kotlin-jvm"}, core.plugins)
        self.assertEqual("junit:junit:4.13.2", str(core.dependencies[0].library))
        self.assertTrue(app.is_android_app)
        self.assertEqual({"namespace": "org.demo", "compileSdk": "37", "minSdk": "26", "targetSdk": "35"}, app.android)
        self.assertEqual(":core", app.dependencies[0].project)
        self.assertIsNone(app.dependencies[1].library.version)
        self.assertEqual([":core", ":app"], [m.path for m in project.in_dependency_order()])

    def test_load_project_unknownDependencyForm_failsNamingTheLine(self):
        self.app('    implementation("com.squareup.okio:okio:3.9.0")')
        with self.assertRaises(BuildError) as e:
            load_project(self.root)
        self.assertIn("app/build.gradle.kts", str(e.exception))
        self.assertIn("okio", str(e.exception))

    def test_load_project_excludeBlock_readsGroupAndModule(self):
        self.app('    testImplementation(libs.junit4) { exclude(group = "org.hamcrest"); exclude(group = "x", module = "y") }')
        dep = load_project(self.root).module(":app").dependencies[0]
        self.assertEqual("junit:junit:4.13.2", str(dep.library))
        self.assertEqual(frozenset({("org.hamcrest", "*"), ("x", "y")}), dep.excludes)

    def test_load_project_unknownStatementInExcludeBlock_fails(self):
        self.app('    testImplementation(libs.junit4) { isTransitive = false }')
        with self.assertRaises(BuildError) as e:
            load_project(self.root)
        self.assertIn("isTransitive", str(e.exception))

    def test_load_project_undeclaredCatalogAlias_fails(self):
        self.app("    implementation(libs.not.there)")
        with self.assertRaises(BuildError) as e:
            load_project(self.root)
        self.assertIn("libs.not.there is not declared", str(e.exception))

    def test_load_project_moduleWithoutBuildFile_fails(self):
        write(self.root, "settings.gradle.kts", 'include(":core")\ninclude(":ghost")\n')
        with self.assertRaises(BuildError) as e:
            load_project(self.root)
        self.assertIn("ghost", str(e.exception))

    def test_load_project_oneLineAndroidBlockAndKspArgs(self):
        write(self.root, "app/build.gradle.kts", """
            plugins {
                alias(libs.plugins.android.application)
            }
            android { namespace = "org.demo"; compileSdk = 37; defaultConfig { minSdk = 26; targetSdk = 35 } }
            ksp {
                arg("room.schemaLocation", "$projectDir/schemas")
            }
        """)
        app = load_project(self.root).module(":app")
        self.assertEqual({"namespace": "org.demo", "compileSdk": "37", "minSdk": "26", "targetSdk": "35"}, app.android)
        self.assertEqual({"room.schemaLocation": os.path.join(self.root, "app") + "/schemas"}, app.ksp_args)

    def test_load_project_serializationPlugin_addsItsCompilerPlugin(self):
        write(self.root, "core/build.gradle.kts", """
            plugins {
                alias(libs.plugins.kotlin.jvm)
                alias(libs.plugins.kotlin.serialization)
            }
        """)
        self.app("")
        core = load_project(self.root).module(":core")
        self.assertEqual({"org.jetbrains.kotlin.jvm", "org.jetbrains.kotlin.plugin.serialization"}, core.plugin_ids)
        self.assertEqual(["tool-serialization-compiler-plugin"], core.compiler_plugins)

    def test_load_project_composeAndSerialization_addBothCompilerPluginsInOrder(self):
        write(self.root, "core/build.gradle.kts", """
            plugins {
                alias(libs.plugins.kotlin.serialization)
                alias(libs.plugins.kotlin.compose)
            }
        """)
        self.app("")
        core = load_project(self.root).module(":core")
        self.assertEqual(["tool-compose-compiler-plugin", "tool-serialization-compiler-plugin"], core.compiler_plugins)

    def test_load_project_noCompilerPluginApplied_addsNone(self):
        self.app("")
        self.assertEqual([], load_project(self.root).module(":core").compiler_plugins)

    def conventions(self, *scripts):
        """A build-logic build with the given (id, script) convention plugins, included as Gradle includes it."""
        write(self.root, "settings.gradle.kts", 'pluginManagement {\n    includeBuild("build-logic")\n}\n'
              'rootProject.name = "demo"\ninclude(":core")\ninclude(":app")\n')
        with open(os.path.join(self.root, "gradle/libs.versions.toml"), "a") as f:
            f.write("".join(f'{plugin_id.replace(".", "-")} = {{ id = "{plugin_id}" }}\n' for plugin_id, _ in scripts))
        for plugin_id, script in scripts:
            write(self.root, f"build-logic/src/main/kotlin/{plugin_id}.gradle.kts", script)
        self.app("")

    LIBRARY_CONVENTION = ("demo.library", """
        plugins { id("org.jetbrains.kotlin.jvm") }
        kotlin { explicitApi() }
        dependencies { testImplementation(libs.findLibrary("junit4").get()) }
    """)

    def test_load_project_conventionPlugin_addsItsPluginsExplicitApiAndDependenciesFirst(self):
        self.conventions(self.LIBRARY_CONVENTION)
        write(self.root, "core/build.gradle.kts", """
            plugins {
                alias(libs.plugins.demo.library)
            }
            dependencies {
                api(libs.kotlin.stdlib)
            }
        """)
        core = load_project(self.root).module(":core")
        self.assertEqual({"kotlin-jvm"}, core.plugins)
        self.assertEqual({"org.jetbrains.kotlin.jvm"}, core.plugin_ids)
        self.assertTrue(core.explicit_api)
        # Gradle runs the convention at the plugins {} block, so its dependencies come before the module's.
        self.assertEqual([("testImplementation", "junit:junit:4.13.2"), ("api", "org.jetbrains.kotlin:kotlin-stdlib:2.4.21")],
                         [(d.configuration, str(d.library)) for d in core.dependencies])
        self.assertEqual([os.path.join(self.root, "build-logic/src/main/kotlin/demo.library.gradle.kts")], core.conventions)

    def test_load_project_conventionApplyingConvention_appliesEachOnceWithItsCompilerPlugin(self):
        self.conventions(self.LIBRARY_CONVENTION, ("demo.library-serialization", """
            plugins {
                id("demo.library")
                id("org.jetbrains.kotlin.plugin.serialization")
            }
        """))
        write(self.root, "core/build.gradle.kts", """
            plugins {
                alias(libs.plugins.demo.library.serialization)
                id("demo.library")
            }
        """)
        core = load_project(self.root).module(":core")
        self.assertEqual({"kotlin-jvm", "kotlin-serialization"}, core.plugins)
        self.assertEqual(["tool-serialization-compiler-plugin"], core.compiler_plugins)
        self.assertEqual(["junit:junit:4.13.2"], [str(d.library) for d in core.dependencies])
        self.assertEqual(["demo.library-serialization.gradle.kts", "demo.library.gradle.kts"],
                         [os.path.basename(c) for c in core.conventions])

    def test_load_project_conventionWithProjectDependencyOrAndroidBlock_failsNamingTheScript(self):
        for script, expected in (('dependencies {\n    testImplementation(project(":app"))\n}\n', "libraries only"),
                                 ('android {\n    namespace = "org.demo"\n}\n', "not android {}")):
            with self.subTest(expected):
                self.setUp()
                self.conventions(("demo.library", script))
                write(self.root, "core/build.gradle.kts", "plugins {\n    alias(libs.plugins.demo.library)\n}\n")
                with self.assertRaises(BuildError) as e:
                    load_project(self.root)
                self.assertIn("demo.library.gradle.kts", str(e.exception))
                self.assertIn(expected, str(e.exception))

    def test_load_project_versionlessCatalogPluginWithoutScript_fails(self):
        self.conventions(self.LIBRARY_CONVENTION)
        with open(os.path.join(self.root, "gradle/libs.versions.toml"), "a") as f:
            f.write('demo-ghost = { id = "demo.ghost" }\n')
        write(self.root, "core/build.gradle.kts", "plugins {\n    alias(libs.plugins.demo.ghost)\n}\n")
        with self.assertRaises(BuildError) as e:
            load_project(self.root)
        self.assertIn("no convention script demo.ghost.gradle.kts", str(e.exception))

    def test_load_project_unknownPluginId_fails(self):
        write(self.root, "core/build.gradle.kts", 'plugins {\n    id("org.example.unknown")\n}\n')
        self.app("")
        with self.assertRaises(BuildError) as e:
            load_project(self.root)
        self.assertIn("org.example.unknown", str(e.exception))

    def test_load_project_thisRepository_conventionsGiveTheLibraryModulesTheirSettings(self):
        project = load_project(REPO)
        for path in (":haptics-core", ":sensor-bridge", ":messaging", ":messaging:broker", ":study", ":gesture"):
            module = project.module(path)
            self.assertTrue(module.explicit_api, path)
            self.assertEqual({"org.jetbrains.kotlin.jvm"}, module.plugin_ids - {SERIALIZATION}, path)
            self.assertIn("junit:junit", [f"{d.library.group}:{d.library.name}" for d in module.deps("testImplementation") if d.library])
        for path in (":haptics-core", ":sensor-bridge", ":messaging", ":study", ":gesture"):
            module = project.module(path)
            self.assertEqual(["tool-serialization-compiler-plugin"], module.compiler_plugins, path)
            self.assertIn("org.jetbrains.kotlinx:kotlinx-serialization-json",
                          [f"{d.library.group}:{d.library.name}" for d in module.deps("implementation", "api") if d.library])
        self.assertEqual([], project.module(":messaging:broker").compiler_plugins)

    def test_compilerArguments_passEachPluginJarAsXplugin(self):
        args = compiler_arguments(sources=["A.kt"], classpath=["x.jar"], output="out", module_name="m",
                                  plugins=["/m2/compose.jar", "/m2/serialization.jar"])
        self.assertEqual(["-Xplugin=/m2/compose.jar", "-Xplugin=/m2/serialization.jar"],
                         [a for a in args if a.startswith("-Xplugin")])
        self.assertEqual("A.kt", args[-1])

    def test_catalog_pluginId_readsTheIdOfTheAlias(self):
        catalog = Catalog(os.path.join(self.root, "gradle/libs.versions.toml"))
        self.assertEqual("org.jetbrains.kotlin.plugin.serialization", catalog.plugin_id("kotlin.serialization"))

    def test_catalog_accessorsIgnoreSeparators(self):
        catalog = Catalog(os.path.join(self.root, "gradle/libs.versions.toml"))
        self.assertEqual("org.jetbrains.kotlin:kotlin-stdlib:2.4.21", str(catalog.library("kotlin.stdlib")))
        self.assertEqual("26", catalog.version("android.minSdk"))


class ArrivalBenchArgsTest(unittest.TestCase):
    def test_arrivalCount_withoutNumber_isTheDocumentedTenThousand(self):
        from hapticon_build.__main__ import arrival_count
        self.assertEqual(10_000, arrival_count(["--arrival"]))

    def test_arrivalCount_givenNumber_isThatNumber(self):
        from hapticon_build.__main__ import arrival_count
        self.assertEqual(200, arrival_count(["--arrival", "200"]))

    def test_arrivalCount_notAWholePositiveNumber_failsNamingIt(self):
        from hapticon_build.__main__ import arrival_count
        for bad in ("0", "-5", "lots"):
            with self.assertRaisesRegex(BuildError, f"not '{bad}'"):
                arrival_count(["--arrival", bad])


class VersionTest(unittest.TestCase):
    def test_highest_ordersLikeGradle(self):
        self.assertEqual("1.10.0", highest(["1.9.0", "1.10.0", "1.10.0-rc01"]))
        self.assertEqual("2.0.0-beta01", highest(["2.0.0-alpha09", "2.0.0-beta01"]))
        self.assertEqual("1.2", highest(["1.2", "1.2-rc1"]))

    def test_concreteVersion_takesExactAndLowerBounds(self):
        self.assertEqual("1.4.0", concrete_version({"strictly": "[1.4.0]"}))
        self.assertEqual("1.0", concrete_version("[1.0,2.0)"))
        self.assertEqual("3.1", concrete_version({"requires": "3.1"}))


class ResolverTest(unittest.TestCase):
    """Resolution against a fabricated local repository (offline)."""

    def setUp(self):
        self.repo = Repository(tempfile.mkdtemp(), offline=True)

    def module(self, g, a, v, deps=(), constraints=(), redirect=None, platform="jvm"):
        variant = {"name": "runtime", "attributes": {"org.gradle.usage": "java-runtime",
                                                      "org.jetbrains.kotlin.platform.type": platform}}
        if redirect:
            variant["available-at"] = dict(zip(("group", "module", "version"), redirect), url="x")
        else:
            variant["files"] = [{"name": f"{a}-{v}.jar", "url": f"{a}-{v}.jar"}]
            variant["dependencies"] = [{"group": dg, "module": da, "version": {"requires": dv}} for dg, da, dv in deps]
            variant["dependencyConstraints"] = [{"group": cg, "module": ca, "version": {"requires": cv}}
                                                for cg, ca, cv in constraints]
        path = self.repo.path(Repository.relative(g, a, v, f"{a}-{v}.module"))
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            json.dump({"variants": [variant]}, f)

    def test_resolve_highestRequestedVersionWins(self):
        self.module("g", "app", "1", deps=[("g", "lib", "1.0"), ("g", "mid", "1")])
        self.module("g", "mid", "1", deps=[("g", "lib", "1.2")])
        self.module("g", "lib", "1.0")
        self.module("g", "lib", "1.2")
        got = {a.name: a.version for a in Resolver(self.repo, "jvm").resolve([("g", "app", "1")])}
        self.assertEqual({"app": "1", "mid": "1", "lib": "1.2"}, got)

    def test_resolve_constraintRaisesVersionInGraph(self):
        self.module("g", "a", "1", deps=[("g", "b", "1.0")], constraints=[("g", "b", "1.5")])
        self.module("g", "b", "1.0")
        self.module("g", "b", "1.5")
        got = {a.name: a.version for a in Resolver(self.repo, "jvm").resolve([("g", "a", "1")])}
        self.assertEqual("1.5", got["b"])

    def test_resolve_followsAvailableAtToPlatformVariant(self):
        self.module("g", "kmp", "2", redirect=("g", "kmp-jvm", "2"))
        self.module("g", "kmp-jvm", "2")
        artifacts = Resolver(self.repo, "jvm").resolve([("g", "kmp", "2")])
        files = [f for a in artifacts for f in a.files]
        self.assertEqual(["g/kmp-jvm/2/kmp-jvm-2.jar"], files)

    def pom(self, g, a, v, body):
        path = self.repo.path(Repository.relative(g, a, v, f"{a}-{v}.pom"))
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(f"<project><groupId>{g}</groupId><artifactId>{a}</artifactId><version>{v}</version>{body}</project>")
        open(self.repo.path(Repository.relative(g, a, v, f"{a}-{v}.module")) + ".404", "w").close()

    def test_resolve_scopeManagedByParentPom_keepsTestDependenciesOut(self):
        self.pom("g", "parent", "1", "<packaging>pom</packaging><dependencyManagement><dependencies>"
                 "<dependency><groupId>t</groupId><artifactId>mockito</artifactId><version>5</version>"
                 "<scope>test</scope></dependency></dependencies></dependencyManagement>")
        self.pom("g", "lib", "1", "<parent><groupId>g</groupId><artifactId>parent</artifactId><version>1</version></parent>"
                 "<dependencies><dependency><groupId>t</groupId><artifactId>mockito</artifactId></dependency>"
                 "</dependencies>")
        got = [a.name for a in Resolver(self.repo, "jvm").resolve([("g", "lib", "1")])]
        self.assertEqual(["lib"], got)

    def test_resolve_rootExclude_dropsGroupFromItsGraph(self):
        self.module("g", "atf", "3", deps=[("google", "material", "1"), ("g", "guava", "2")])
        self.module("g", "guava", "2")
        got = [a.name for a in Resolver(self.repo, "jvm").resolve([("g", "atf", "3", frozenset({("google", "*")}))])]
        self.assertEqual(["atf", "guava"], got)

    def test_resolve_versionlessRootWithoutPlatform_fails(self):
        self.module("g", "a", "1")
        with self.assertRaises(BuildError) as e:
            Resolver(self.repo, "jvm").resolve([("g", "a", "1"), ("g", "nobom", None)])
        self.assertIn("no version for g:nobom", str(e.exception))


class PackagingTest(unittest.TestCase):
    def test_excluded_followsAgpDefaults(self):
        self.assertTrue(excluded("META-INF/MANIFEST.MF"))
        self.assertTrue(excluded("META-INF/maven/org.x/y/pom.xml"))
        self.assertTrue(excluded("org/x/Foo.class"))
        self.assertTrue(excluded("kotlin/collections/collections.kotlin_metadata"))
        self.assertFalse(excluded("META-INF/androidx.core_core.version"))
        self.assertFalse(excluded("kotlin/kotlin.kotlin_builtins"))
        self.assertFalse(excluded("META-INF/services/kotlinx.coroutines.internal.MainDispatcherFactory"))


if __name__ == "__main__":
    unittest.main()


class ReleaseTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp()
        self.keystore = os.path.join(self.dir, "release.jks")
        open(self.keystore, "w").close()

    def test_signing_fromArgs_optionsWinOverEnvironment_passwordsOnlyFromEnvironment(self):
        env = {"HAPTICON_RELEASE_KEYSTORE": "/nowhere.jks", "HAPTICON_RELEASE_KEY_ALIAS": "env-alias",
               "HAPTICON_RELEASE_STORE_PASSWORD": "s3cret"}
        signing = Signing.from_args(["--release", "--keystore", self.keystore, "--key-alias", "hapticon"], env)
        self.assertEqual(Signing(self.keystore, "hapticon", "s3cret", "s3cret"), signing)

    def test_signing_fromArgs_noPassword_failsNamingTheVariables(self):
        with self.assertRaises(BuildError) as e:
            Signing.from_args(["--keystore", self.keystore, "--key-alias", "a"], {})
        self.assertIn("HAPTICON_RELEASE_STORE_PASSWORD", str(e.exception))

    def test_signing_fromArgs_missingKeystoreFile_fails(self):
        with self.assertRaises(BuildError) as e:
            Signing.from_args(["--keystore", self.keystore + ".gone", "--key-alias", "a"],
                              {"HAPTICON_RELEASE_STORE_PASSWORD": "x"})
        self.assertIn("not found", str(e.exception))

    def test_requiredClasses_roomImplsManifestComponentsAndReflectiveClasses(self):
        import zipfile
        program = os.path.join(self.dir, "program.jar")
        with zipfile.ZipFile(program, "w") as z:
            for n in ("org/x/data/AppDatabase_Impl.class", "org/x/data/MessageDao_Impl.class",
                      "org/x/data/MessageDao_Impl$1.class", "org/x/Other.class"):
                z.writestr(n, b"")
        manifest = os.path.join(self.dir, "AndroidManifest.xml")
        with open(manifest, "w") as f:
            f.write('<manifest package="org.x"><application android:name=".App">'
                    '<activity android:exported="true"\n android:name="org.x.MainActivity"/></application></manifest>')
        got = required_classes(program, manifest)
        for name in ("org.x.data.AppDatabase_Impl", "org.x.data.MessageDao_Impl", "org.x.App", "org.x.MainActivity",
                     *REFLECTIVE_CLASSES):
            self.assertIn(name, got)
        self.assertNotIn("org.x.Other", got)
        self.assertFalse(any("$" in n for n in got))


class RobolectricSdkTest(unittest.TestCase):
    """The instrumented SDK jars Robolectric runs on (targetSdk's and 36's) land in the one directory it reads."""

    def setUp(self):
        self.root = tempfile.mkdtemp()
        write(self.root, "gradle/libs.versions.toml", """
            [versions]
            android-all-instrumented = "15-robolectric-13954326-i7"
            android-all-instrumented-36 = "16-robolectric-13921718-i7"
            [libraries]
            tool-android-all-instrumented = { module = "org.robolectric:android-all-instrumented", version.ref = "android-all-instrumented" }
            tool-android-all-instrumented-36 = { module = "org.robolectric:android-all-instrumented", version.ref = "android-all-instrumented-36" }
            tool-android-all-runtime = { module = "org.robolectric:android-all", version = "15-robolectric-13954326" }
        """)
        write(self.root, "settings.gradle.kts", 'rootProject.name = "demo"\ninclude(":core")\n')
        write(self.root, "core/build.gradle.kts", "plugins {\n}\n")
        self.repo = Repository(tempfile.mkdtemp(), offline=True)
        self.jars = {}
        for version in ("15-robolectric-13954326-i7", "16-robolectric-13921718-i7"):
            rel = Repository.relative("org.robolectric", "android-all-instrumented", version,
                                      f"android-all-instrumented-{version}.jar")
            path = self.repo.path(rel)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w") as f:
                f.write(version)
            self.jars[version] = path

    def test_catalog_toolAliases_listsEveryInstrumentedSdkAndNothingElse(self):
        catalog = Catalog(os.path.join(self.root, "gradle/libs.versions.toml"))
        self.assertEqual(["tool-android-all-instrumented", "tool-android-all-instrumented-36"],
                         catalog.tool_aliases("tool-android-all-instrumented"))

    def test_robolectricSdkDir_linksBothJarsUnderTheNamesLocalDependencyResolverLooksFor(self):
        from hapticon_build.toolchain import Toolchain
        tools = Toolchain(load_project(self.root), self.repo, tempfile.mkdtemp())
        sdk_dir = tools.robolectric_sdk_dir
        self.assertEqual(["android-all-instrumented-15-robolectric-13954326-i7.jar",
                          "android-all-instrumented-16-robolectric-13921718-i7.jar"],
                         sorted(n for n in os.listdir(sdk_dir) if n.endswith(".jar")))
        for version, path in self.jars.items():
            with open(os.path.join(sdk_dir, f"android-all-instrumented-{version}.jar")) as f:
                self.assertEqual(version, f.read())

    def test_robolectricSdkDir_noInstrumentedJarDeclared_failsNamingTheAlias(self):
        from hapticon_build.toolchain import Toolchain
        write(self.root, "gradle/libs.versions.toml", "[versions]\n[libraries]\n")
        tools = Toolchain(load_project(self.root), self.repo, tempfile.mkdtemp())
        with self.assertRaises(BuildError) as e:
            tools.robolectric_sdk_dir
        self.assertIn("tool-android-all-instrumented", str(e.exception))


class Sdk36JavaTest(unittest.TestCase):
    """Tests on SDK 36 need a JDK 21+ (its framework jar is Java 21 bytecode); the build finds one or says what to install."""

    def setUp(self):
        # The choice reads HAPTICON_TEST_JAVA_HOME first; a developer's setting must not decide these tests.
        saved = os.environ.pop("HAPTICON_TEST_JAVA_HOME", None)
        if saved is not None:
            self.addCleanup(os.environ.__setitem__, "HAPTICON_TEST_JAVA_HOME", saved)

    def jdk(self, release):
        home = tempfile.mkdtemp()
        os.makedirs(os.path.join(home, "bin"))
        open(os.path.join(home, "bin", "java"), "w").close()
        with open(os.path.join(home, "release"), "w") as f:
            f.write(f'IMPLEMENTOR="x"\nJAVA_VERSION="{release}"\n')
        return home

    def test_javaForSdk36_buildJdk17_picksTheNewest21PlusBesideIt(self):
        from hapticon_build.toolchain import java_for_sdk36
        old, jdk21, jdk25 = self.jdk("17.0.15"), self.jdk("21.0.4"), self.jdk("25.0.3")
        self.assertEqual(os.path.join(jdk25, "bin", "java"), java_for_sdk36(old, [old, jdk21, jdk25, "/nonexistent"]))

    def test_javaForSdk36_buildJdkIs21_usesIt(self):
        from hapticon_build.toolchain import java_for_sdk36
        jdk21 = self.jdk("21.0.4")
        self.assertEqual(os.path.join(jdk21, "bin", "java"), java_for_sdk36(jdk21, []))

    def test_javaForSdk36_noneInstalled_usesTheFetchedRuntime(self):
        from hapticon_build.toolchain import java_for_sdk36
        old, fetched = self.jdk("17.0.15"), self.jdk("25.0.2")
        self.assertEqual(os.path.join(fetched, "bin", "java"), java_for_sdk36(old, [old], fetch=lambda: fetched))
        # An installed 21+ wins; the fetch is not even tried.
        jdk21 = self.jdk("21.0.4")
        self.assertEqual(os.path.join(jdk21, "bin", "java"), java_for_sdk36(old, [old, jdk21], fetch=lambda: self.fail("fetched")))

    def test_javaForSdk36_none_failsNamingThePackage(self):
        from hapticon_build.toolchain import java_for_sdk36
        old = self.jdk("17.0.15")
        with self.assertRaises(BuildError) as e:
            java_for_sdk36(old, [old])
        self.assertIn("openjdk-21-jdk-headless", str(e.exception))


FIXTURES = os.path.join(os.path.dirname(__file__), "fixtures", "dex")
FIELDS_DEX = os.path.join(FIXTURES, "fields.dex")  # D8 output of fixtures/dex/Fields.java (how: its header)
FIELDS_R8_DEX = os.path.join(FIXTURES, "fields-r8.dex")  # R8 9.5.28 output of the same, fields renamed
FIELDS_R8_MAPPING = os.path.join(FIXTURES, "fields-r8-mapping.txt")


def read(path: str, mode: str = "r"):
    with open(path, mode) as f:
        return f.read()


def javac(out: str, sources: dict[str, str]) -> None:
    """Compiles `sources` (path → text) into `out` with the JDK the build runs on."""
    for path, text in sources.items():
        write(out + "-src", path, text)
    files = [os.path.join(out + "-src", p) for p in sources]
    subprocess.run(["javac", "--release", "8", "-d", out, *files], check=True, capture_output=True)


class DexParserTest(unittest.TestCase):
    def test_dexClasses_fieldsFixture_classesSuperclassesMethodsAndFields(self):
        classes = dex_classes(read(FIELDS_DEX, "rb"))
        self.assertEqual({
            "Lfixture/Fields;": DexClass("Ljava/lang/Object;", frozenset({
                "<clinit>()V", "<init>()V", "<init>(ILjava/lang/String;)V", "declared()I"}), frozenset({
                "COUNT:Ljava/util/concurrent/atomic/AtomicIntegerFieldUpdater;",
                "NAME:Ljava/util/concurrent/atomic/AtomicReferenceFieldUpdater;", "count:I", "name:Ljava/lang/String;"})),
            "Lfixture/Fields$Child;": DexClass("Lfixture/Fields;", frozenset({"<init>()V", "touch()V"}), frozenset()),
        }, classes)

    def test_dexFieldLookups_d8Output_updaterAndGetDeclaredFieldNames(self):
        self.assertEqual({("Lfixture/Fields;", "count"), ("Lfixture/Fields;", "name")},
                         dex_field_lookups(read(FIELDS_DEX, "rb")))

    def test_dexFieldLookups_r8Output_namesRewrittenToTheNewFieldNames(self):
        # What R8 9.5.28 does itself for newUpdater(X.class, "f") and X.class.getDeclaredField("f"): the const-string
        # becomes the field's new name; neither "count" nor "name" is left in the dex.
        dex = read(FIELDS_R8_DEX, "rb")
        self.assertEqual({("Lfixture/Fields;", "a"), ("Lfixture/Fields;", "b")}, dex_field_lookups(dex))
        self.assertNotIn(b"\x05count\x00", dex)
        self.assertEqual({"a:I", "b:Ljava/lang/String;", "c:Ljava/util/concurrent/atomic/AtomicIntegerFieldUpdater;"},
                         set(dex_classes(dex)["Lfixture/Fields;"].fields))

    def test_readFieldMapping_r8Mapping_fieldRenamesOnly(self):
        self.assertEqual({("fixture.Fields", "count"): "a", ("fixture.Fields", "name"): "b", ("fixture.Fields", "COUNT"): "c"},
                         read_field_mapping(FIELDS_R8_MAPPING))
        self.assertEqual({}, read_field_mapping(None))

    def test_dexTypeNames_fieldsFixture_theClassesDexClassesReads(self):
        from hapticon_build.android import dex_type_names
        self.assertEqual({"Lfixture/Fields;", "Lfixture/Fields$Child;"}, dex_type_names(read(FIELDS_DEX, "rb")))

    def test_appClassReferences_javacOutput_classesNamedIncludingArrayElementsNotPrimitives(self):
        import zipfile
        from hapticon_build.android import app_class_references
        tmp = tempfile.mkdtemp()
        javac(os.path.join(tmp, "classes"), {
            "app/Main.java": "package app; public class Main { Object run() { new lib.Helper(); int[] n = new int[2];"
                             " return new lib.Item[n.length]; } }",
            "lib/Helper.java": "package lib; public class Helper {}",
            "lib/Item.java": "package lib; public class Item {}",
        })
        program = os.path.join(tmp, "program.jar")
        with zipfile.ZipFile(program, "w") as z:
            z.write(os.path.join(tmp, "classes", "app", "Main.class"), "app/Main.class")
        self.assertEqual({"Lapp/Main;", "Llib/Helper;", "Llib/Item;", "Ljava/lang/Object;"}, app_class_references(program))

    def test_dexClasses_notDex_fails(self):
        with self.assertRaises(BuildError):
            dex_classes(b"PK\x03\x04" + bytes(200))

    @mock.patch("hapticon_build.android.FIELD_LOOKUP_PACKAGES", ("fixture.",))
    def test_fieldLookups_javacOutput_updaterAndGetDeclaredFieldTargets(self):
        out = os.path.join(tempfile.mkdtemp(), "classes")
        javac(out, {"fixture/Fields.java": read(os.path.join(FIXTURES, "Fields.java"))})
        self.assertEqual({("fixture.Fields", "count"), ("fixture.Fields", "name")},
                         field_lookups(read(os.path.join(out, "fixture", "Fields.class"), "rb")))
        self.assertEqual(set(), field_lookups(read(os.path.join(out, "fixture", "Fields$Child.class"), "rb")))
        with mock.patch("hapticon_build.android.FIELD_LOOKUP_PACKAGES", ("io.netty.",)):  # outside the checked packages
            self.assertEqual(set(), field_lookups(read(os.path.join(out, "fixture", "Fields.class"), "rb")))


class SmokeCheckTest(unittest.TestCase):
    def test_smokeCheck_presentClassesAndMembers_countsThem(self):
        self.assertEqual((2, 3, 0), smoke_check([FIELDS_DEX], ["fixture.Fields", "fixture.Fields$Child"], [
            ("fixture.Fields", "<init>()V"), ("fixture.Fields", "count"), ("fixture.Fields$Child", "touch()V")]))

    def test_smokeCheck_missingConstructor_failsNamingIt(self):
        with self.assertRaises(BuildError) as e:
            smoke_check([FIELDS_DEX], [], [("fixture.Fields$Child", "<init>(I)V"), ("fixture.Fields", "<init>()V")])
        self.assertIn("lacks 1 members reached by name", str(e.exception))
        self.assertIn("fixture.Fields$Child.<init>(I)V", str(e.exception))

    def test_smokeCheck_fieldOfRenamedClassMissing_failsNamingBothNames(self):
        mapping = {"org.jctools.queues.Queue": "fixture.Fields"}
        self.assertEqual((0, 1, 0), smoke_check([FIELDS_DEX], [], [("org.jctools.queues.Queue", "count")], mapping))
        with self.assertRaises(BuildError) as e:  # the code still loads "count" for a lookup; Child lacks it
            smoke_check([FIELDS_DEX], [], [("org.jctools.queues.Queue", "count")],
                        {"org.jctools.queues.Queue": "fixture.Fields$Child"})
        self.assertIn("org.jctools.queues.Queue (renamed fixture.Fields$Child).count", str(e.exception))

    def test_smokeCheck_fieldsRenamedWithTheirUpdaterNames_countsThemRewritten(self):
        # R8 renamed count -> a, name -> b and its output's newUpdater/getDeclaredField calls name a and b.
        fields = read_field_mapping(FIELDS_R8_MAPPING)
        self.assertEqual((0, 2, 2), smoke_check([FIELDS_R8_DEX], [], [("fixture.Fields", "count"), ("fixture.Fields", "name")],
                                                read_mapping(FIELDS_R8_MAPPING), fields))

    def test_smokeCheck_renamedFieldNoLookupNames_failsNamingNewName(self):
        # The updater field COUNT was renamed c, but no lookup in the dex names c: its string was not rewritten.
        with self.assertRaises(BuildError) as e:
            smoke_check([FIELDS_R8_DEX], [], [("fixture.Fields", "COUNT")], {}, read_field_mapping(FIELDS_R8_MAPPING))
        self.assertIn("fixture.Fields.COUNT (renamed c, which no lookup in the R8 output names)", str(e.exception))

    def test_smokeCheck_removedFieldWhoseNameNoCodeLoads_notRequired(self):
        # R8 removed the updater field NAME (nothing used it); no code in the dex loads the string "NAME".
        self.assertEqual((0, 0, 0), smoke_check([FIELDS_R8_DEX], [], [("fixture.Fields", "NAME")], {},
                                                read_field_mapping(FIELDS_R8_MAPPING)))
        self.assertNotIn("NAME", dex_code_strings(read(FIELDS_R8_DEX, "rb")))

    def test_smokeCheck_missingFieldWhoseNameCodeStillLoads_fails(self):
        # Fields.<clinit> still loads "a" for its newUpdater; Child declares no field a.
        self.assertIn("a", dex_code_strings(read(FIELDS_R8_DEX, "rb")))
        with self.assertRaises(BuildError) as e:
            smoke_check([FIELDS_R8_DEX], [], [("fixture.Fields$Child", "a")])
        self.assertIn("fixture.Fields$Child.a", str(e.exception))

    def test_smokeCheck_memberOfRemovedClass_notRequired(self):
        self.assertEqual((0, 0, 0), smoke_check([FIELDS_DEX], [], [("org.gone.Queue", "producerIndex")]))

    def test_smokeCheck_missingClass_failsNamingIt(self):
        with self.assertRaises(BuildError) as e:
            smoke_check([FIELDS_DEX], ["fixture.Fields", "org.x.Gone"])
        self.assertIn("lacks classes reached by name", str(e.exception))
        self.assertIn("org.x.Gone", str(e.exception))

    @mock.patch("hapticon_build.android.FIELD_LOOKUP_PACKAGES", ("fixture.",))
    def test_requiredMembers_roomDatabaseImplConstructorLibraryFieldsAndReflectiveMembers(self):
        import zipfile
        tmp = tempfile.mkdtemp()
        classes = os.path.join(tmp, "classes")
        javac(classes, {
            "androidx/room/RoomDatabase.java": "package androidx.room; public abstract class RoomDatabase {}",
            "org/x/AppDatabase.java": "package org.x; public abstract class AppDatabase extends androidx.room.RoomDatabase {}",
            "org/x/AppDatabase_Impl.java": "package org.x; public final class AppDatabase_Impl extends AppDatabase {}",
            "org/x/MessageDao_Impl.java": "package org.x; public final class MessageDao_Impl { MessageDao_Impl(AppDatabase d) {} }",
            "fixture/Fields.java": read(os.path.join(FIXTURES, "Fields.java")),
        })
        program, library = os.path.join(tmp, "program.jar"), os.path.join(tmp, "library.jar")
        for jar, folder in ((program, "org/x"), (library, "fixture")):
            with zipfile.ZipFile(jar, "w") as z:
                for f in sorted(os.listdir(os.path.join(classes, folder))):
                    z.write(os.path.join(classes, folder, f), f"{folder}/{f}")
        expected = sorted({("org.x.AppDatabase_Impl", "<init>()V"), ("fixture.Fields", "count"),
                           ("fixture.Fields", "name"), *REFLECTIVE_MEMBERS})
        cache = os.path.join(tmp, "cache")
        self.assertEqual(expected, required_members(program, [library], cache))
        self.assertEqual(1, len(os.listdir(cache)))  # the library's lookups, read from here the next time
        self.assertEqual(expected, required_members(program, [library], cache))


class LibraryDexTest(unittest.TestCase):
    """The debug APK's library dex (dexing.py, java/LibraryDexer.java) with the project's own D8 (r8 from the
    catalog). D8 takes seconds per run, so the class dexes two small jars once and the tests build on that cache."""

    @classmethod
    def setUpClass(cls):
        import zipfile
        from hapticon_build.builder import Build
        from hapticon_build.dexing import D8Tool, dex_libraries, library_globals
        tools = Build(load_project(REPO)).tools
        cls.tmp = tempfile.mkdtemp()
        classes = os.path.join(cls.tmp, "classes")
        javac(classes, {
            "lib/a/Greeter.java": "package lib.a; public interface Greeter { default String greet() { return \"hi\"; } }",
            "lib/a/Hello.java": "package lib.a; public class Hello implements Greeter { public Runnable r() { return () -> {}; } }",
            "lib/b/Counter.java": "package lib.b; public class Counter { public Runnable count(int[] xs) { return () -> {}; } }",
            "lib/c/Other.java": "package lib.c; public class Other { }",
        })
        cls.jars = []
        for name, folder in (("a.jar", "lib/a"), ("b.jar", "lib/b"), ("c.jar", "lib/c")):
            jar = os.path.join(cls.tmp, name)
            with zipfile.ZipFile(jar, "w") as z:
                for f in sorted(os.listdir(os.path.join(classes, folder))):
                    z.write(os.path.join(classes, folder, f), f"{folder}/{f}")
            cls.jars.append(jar)
        cls.cache = os.path.join(cls.tmp, "cache")
        helper = tools.helper_classes("LibraryDexer", [tools.r8])
        cls.tool = D8Tool(java=tools.java, classpath=[helper, tools.r8], r8_jar=tools.r8, android_jar=tools.android_jar,
                          java_home=tools.java_home, min_sdk="26", cache=cls.cache, threads=2)
        cls.first = dex_libraries(cls.jars[:2], cls.tool)
        cls.first_defined = cls.defined(cls.first)  # read now: a later test's set replaces this one
        cls.first_globals = library_globals(cls.first)
        cls.cached_jars = sorted(os.listdir(os.path.join(cls.cache, "dex", "jars")))
        with mock.patch("subprocess.Popen", side_effect=AssertionError("D8 ran again")):
            cls.again = dex_libraries(cls.jars[:2], cls.tool)  # before any test dexes another set

    @staticmethod
    def defined(dexes):
        from hapticon_build.android import dex_type_names
        return set().union(*(dex_type_names(read(d, "rb")) for d in dexes))

    def dex_recording_jobs(self, jars) -> tuple[list[str], list[str]]:
        """dex_libraries(jars) and the jars it gave LibraryDexer (`-` for one already dexed)."""
        from hapticon_build.dexing import dex_libraries
        jobs, real_popen = [], subprocess.Popen

        def popen(cmd, **kwargs):
            with open(cmd[-2]) as f:
                jobs.extend(line.split("\t")[0] for line in f.read().splitlines())
            return real_popen(cmd, **kwargs)
        with mock.patch("subprocess.Popen", side_effect=popen):
            return dex_libraries(jars, self.tool), jobs

    def test_dexLibraries_twoJars_mergedDexDefinesEveryClassAndEachJarIsCached(self):
        defined = self.first_defined
        self.assertLessEqual({"Llib/a/Greeter;", "Llib/a/Hello;", "Llib/b/Counter;"}, defined)
        # Both jars' lambdas are desugared by D8, which marks each with a global synthetic annotation class: not in
        # the merged dex, but kept apart for each jar, to be compiled once with the app's.
        self.assertTrue(any(d.startswith("Llib/b/Counter$") for d in defined))
        self.assertNotIn("Lcom/android/tools/r8/annotations/LambdaMethod;", defined)
        self.assertEqual(["0.zip", "1.zip"], [os.path.basename(g) for g in self.first_globals])
        self.assertEqual(2, len(self.cached_jars))
        self.assertIn("timing.json", os.listdir(os.path.join(self.cache, "dex")))

    def test_dexLibraries_sameJarsAgain_runsNoD8(self):
        self.assertEqual(self.first, self.again)  # setUpClass made D8 fail had it run

    def test_dexLibraries_cachedJarElsewhereAndANewOne_dexesOnlyTheNewOneThenMerges(self):
        import shutil
        copy = os.path.join(tempfile.mkdtemp(), "a.jar")  # the same content under another path: still cached
        shutil.copyfile(self.jars[0], copy)
        dexes, jobs = self.dex_recording_jobs([copy, self.jars[2]])
        self.assertEqual(["-", self.jars[2]], jobs)
        self.assertLessEqual({"Llib/a/Hello;", "Llib/c/Other;"}, self.defined(dexes))
        self.assertNotIn("Llib/b/Counter;", self.defined(dexes))
        self.assertEqual(1, len(os.listdir(os.path.join(self.cache, "dex", "libraries"))))  # the old set is gone
        self.assertLessEqual(set(self.cached_jars), set(os.listdir(os.path.join(self.cache, "dex", "jars"))))

    def test_dexLibraries_classInTwoJars_failsNamingItAndKeepsNoMergedSet(self):
        import zipfile
        other = os.path.join(tempfile.mkdtemp(), "other.jar")  # another jar that also defines lib.b.Counter
        with zipfile.ZipFile(self.jars[1]) as source, zipfile.ZipFile(other, "w") as z:
            z.writestr("lib/b/Counter.class", source.read("lib/b/Counter.class"))
            z.writestr("README", "a different jar")
        with self.assertRaises(BuildError) as e:
            self.dex_recording_jobs([self.jars[1], other])
        self.assertIn("lib.b.Counter", str(e.exception))
        merged = os.listdir(os.path.join(self.cache, "dex", "libraries"))
        self.assertFalse([m for m in merged if ".tmp" in m])  # no half-merged set left behind


class ModuleDexTest(unittest.TestCase):
    """The app's own modules' dex (dexing.dex_modules, module_jar): each module dexed alone, kept by content, only the
    changed module dexed again. D8 takes seconds per run, so the class dexes two modules once and the tests build on
    that cache."""

    @classmethod
    def setUpClass(cls):
        from hapticon_build.builder import Build
        from hapticon_build.dexing import D8Tool, dex_modules, module_jar
        tools = Build(load_project(REPO)).tools
        cls.tmp = tempfile.mkdtemp()
        cls.classes = {}
        for module, source in (("core", "package m.core; public class Core { public Runnable r() { return () -> {}; } }"),
                               ("ui", "package m.ui; public class Screen { public int n() { return 1; } }")):
            out = os.path.join(cls.tmp, module)
            javac(out, {f"m/{module}/{'Core' if module == 'core' else 'Screen'}.java": source})
            cls.classes[module] = out
        helper = tools.helper_classes("LibraryDexer", [tools.r8])
        cls.cache = os.path.join(cls.tmp, "cache")
        cls.tool = D8Tool(java=tools.java, classpath=[helper, tools.r8], r8_jar=tools.r8, android_jar=tools.android_jar,
                          java_home=tools.java_home, min_sdk="26", cache=cls.cache, threads=2)
        cls.jars = [os.path.join(cls.tmp, f"{m}.jar") for m in ("core", "ui")]
        for m, jar in zip(("core", "ui"), cls.jars):
            module_jar(cls.classes[m], jar)
        cls.first = dex_modules(cls.jars, cls.tool)
        # read now: a later test replaces ui's dex
        cls.first_defined = [cls.defined(d) for d in cls.first]
        cls.first_globals = [cls.global_synthetics(d) for d in cls.first]
        with mock.patch("subprocess.Popen", side_effect=AssertionError("D8 ran again")):
            cls.again = dex_modules(cls.jars, cls.tool)

    @staticmethod
    def global_synthetics(directory):
        import zipfile
        path = os.path.join(directory, "globals.zip")
        return zipfile.ZipFile(path).namelist() if os.path.exists(path) else []

    @staticmethod
    def defined(directory):
        from hapticon_build.android import dex_type_names
        from hapticon_build.dexing import dex_files
        return set().union(*(dex_type_names(read(d, "rb")) for d in dex_files(directory)))

    def test_dexModules_twoModules_eachDexDefinesItsOwnClassesOnly(self):
        core, ui = self.first_defined
        self.assertIn("Lm/core/Core;", core)
        self.assertTrue(any(d.startswith("Lm/core/Core$") for d in core))  # its lambda, desugared
        self.assertNotIn("Lm/ui/Screen;", core)
        self.assertEqual({"Lm/ui/Screen;"}, ui)
        # core's lambda needs D8's global LambdaMethod annotation: kept apart, to be compiled once with the others'.
        self.assertEqual([["classes.globals"], []], self.first_globals)

    def test_dexModules_sameClassesAgain_runsNoD8(self):
        self.assertEqual(self.first, self.again)  # setUpClass made D8 fail had it run

    def test_moduleJar_sameClassesWrittenLater_sameKey(self):
        from hapticon_build.dexing import jar_key, module_jar
        later = os.path.join(tempfile.mkdtemp(), "ui.jar")
        for root, _dirs, files in os.walk(self.classes["ui"]):
            for f in files:
                os.utime(os.path.join(root, f), (1e9, 1e9))  # recompiled to the same bytes: another time stamp
        self.assertTrue(module_jar(self.classes["ui"], later))
        self.assertEqual(jar_key(self.jars[1], self.tool), jar_key(later, self.tool))

    def test_moduleJar_noClasses_writesNothing(self):
        from hapticon_build.dexing import module_jar
        resources = tempfile.mkdtemp()
        write(resources, "icons/knock.json", "{}")
        jar = os.path.join(resources, "r.jar")
        self.assertFalse(module_jar(resources, jar))
        self.assertFalse(os.path.exists(jar))

    def test_dexModules_oneModuleChanged_dexesOnlyItAndDropsItsOldDex(self):
        from hapticon_build.dexing import dex_modules, module_jar
        changed = os.path.join(tempfile.mkdtemp(), "ui")
        javac(changed, {"m/ui/Screen.java": "package m.ui; public class Screen { public int n() { return 2; } }"})
        jar = os.path.join(os.path.dirname(changed), "ui.jar")
        module_jar(changed, jar)
        jobs, real_popen = [], subprocess.Popen

        def popen(cmd, **kwargs):
            with open(cmd[-2]) as f:
                jobs.extend(line.split("\t")[0] for line in f.read().splitlines())
            self.assertEqual("-", cmd[-1])  # nothing merged
            return real_popen(cmd, **kwargs)
        with mock.patch("subprocess.Popen", side_effect=popen):
            dirs = dex_modules([self.jars[0], jar], self.tool)
        self.assertEqual(["-", jar], jobs)
        self.assertEqual(self.first[0], dirs[0])
        self.assertNotEqual(self.first[1], dirs[1])
        self.assertEqual({"Lm/ui/Screen;"}, self.defined(dirs[1]))
        self.assertEqual(sorted(os.path.basename(d) for d in dirs),
                         sorted(os.listdir(os.path.join(self.cache, "dex", "modules"))))  # the old ui dex is gone

    def test_definedTwice_typeInTwoDexFiles_namesOnlyIt(self):
        from hapticon_build.android import defined_twice
        self.assertEqual({"La/B;"}, defined_twice([{"La/A;", "La/B;"}, {"La/B;", "La/C;"}, {"La/D;"}]))
        self.assertEqual(set(), defined_twice([{"La/A;"}, {"La/C;"}]))


class SharedDexCacheTest(unittest.TestCase):
    def test_sharedDexCache_variableWins_thenXdgCacheHome_thenHomeCache(self):
        from hapticon_build.dexing import shared_dex_cache
        self.assertEqual("/d", shared_dex_cache({"HAPTICON_DEX_CACHE": "/d", "XDG_CACHE_HOME": "/x"}, "/h"))
        self.assertEqual("/x/hapticon/dex", shared_dex_cache({"XDG_CACHE_HOME": "/x"}, "/h"))
        self.assertEqual("/h/.cache/hapticon/dex", shared_dex_cache({}, "/h"))

    def test_d8Tool_sharedCache_holdsJarsAndMergedSets_elseTheProjectCacheDoes(self):
        from hapticon_build.dexing import D8Tool
        tool = D8Tool("java", [], "r8.jar", "android.jar", "/jdk", "26", "/p/.build-cache", 2)
        self.assertEqual(("/p/.build-cache/dex/jars", "/p/.build-cache/dex/libraries"),
                         (tool.jars_root, tool.libraries_root))
        shared = D8Tool("java", [], "r8.jar", "android.jar", "/jdk", "26", "/p/.build-cache", 2, shared="/u/dex")
        self.assertEqual(("/u/dex/jars", "/u/dex/libraries"), (shared.jars_root, shared.libraries_root))


    def test_writeJobs_freshCloneWithTheDexCacheElsewhere_makesItsDirectory(self):
        # A fresh clone with HAPTICON_DEX_CACHE elsewhere has no .build-cache/dex/ yet; the first demo failed there.
        import tempfile
        from hapticon_build.dexing import D8Tool, write_jobs
        with tempfile.TemporaryDirectory() as project:
            cache = os.path.join(project, ".build-cache")
            tool = D8Tool("java", [], "r8.jar", "android.jar", "/jdk", "26", cache, 2, shared=os.path.join(project, "shared"))
            path = write_jobs(tool, [("a.jar", "/out/a"), ("b.jar", "-")])
            self.assertEqual(os.path.join(cache, "dex"), os.path.dirname(path))
            with open(path) as f:
                self.assertEqual("a.jar\t/out/a\nb.jar\t-\n", f.read())

class ProgressTest(unittest.TestCase):
    def test_progress_beforeAndPastTheEstimate(self):
        from hapticon_build.ui import progress
        self.assertEqual("12 s, ~30 s left", progress(12.2, 42.0))
        self.assertEqual("50 s, longer than the ~42 s expected", progress(50.0, 42.0))

    def test_stageTimes_recordedDurationIsTheNextRunsEstimate(self):
        from hapticon_build.ui import Stage, StageTimes
        path = os.path.join(tempfile.mkdtemp(), "cache", "stage-times.json")
        times = StageTimes(path)
        self.assertEqual(63.0, times.expected("compile :core main", 63.0))  # never timed: the default
        with mock.patch("time.monotonic", side_effect=[100.0, 141.5]), mock.patch("sys.stderr"):
            with Stage("compile :core main (63 files)", None, times, "compile :core main"):
                pass
        self.assertEqual(41.5, StageTimes(path).expected("compile :core main", 63.0))

    def test_stageTimes_failedStage_recordsNothing(self):
        from hapticon_build.ui import Stage, StageTimes
        times = StageTimes(os.path.join(tempfile.mkdtemp(), "stage-times.json"))
        with self.assertRaises(BuildError), mock.patch("sys.stderr"):
            with Stage("compile :core main", 10.0, times):
                raise BuildError("e: a.kt:1:1 Unresolved reference")
        self.assertEqual(10.0, times.expected("compile :core main", 10.0))

    def test_stage_longStage_printsElapsedAndEstimateWhileRunning(self):
        import io
        from hapticon_build import ui
        err = io.StringIO()
        with mock.patch.object(ui, "HEARTBEAT_S", 0.05), mock.patch("sys.stderr", err):
            with ui.Stage("compile :app main", 1000.0):
                import time
                time.sleep(0.3)
        beats = [line for line in err.getvalue().splitlines() if "left" in line]
        self.assertTrue(beats)
        self.assertRegex(beats[0], r"^  compile :app main: 0 s, ~1000 s left$")


class ModuleJarTest(unittest.TestCase):
    def test_moduleJar_fromAJar_copiesItsClassesSortedWithFixedTimes(self):
        import zipfile
        from hapticon_build.dexing import module_jar
        tmp = tempfile.mkdtemp()
        source, jar = os.path.join(tmp, "R.jar"), os.path.join(tmp, "out.jar")
        with zipfile.ZipFile(source, "w") as z:
            z.writestr("org/x/R$string.class", b"\xca\xfe\xba\xbe2")
            z.writestr("org/x/R.class", b"\xca\xfe\xba\xbe1")
            z.writestr("META-INF/MANIFEST.MF", "Manifest-Version: 1.0\n")
        self.assertTrue(module_jar(source, jar))
        with zipfile.ZipFile(jar) as z:
            self.assertEqual(["org/x/R$string.class", "org/x/R.class"], z.namelist())
            self.assertEqual(b"\xca\xfe\xba\xbe1", z.read("org/x/R.class"))
            self.assertEqual({(1980, 1, 1, 0, 0, 0)}, {i.date_time for i in z.infolist()})
            self.assertEqual({zipfile.ZIP_STORED}, {i.compress_type for i in z.infolist()})
