"""The dependency rules of docs/architecture.md: the project follows them, and the check catches breaking them."""
import itertools
import os
import tempfile
import textwrap
import unittest

from hapticon_build.architecture import check, cycles, read_rules

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))

DOC = """
# Architecture
## Rules
### Who may use whom
| module | its main code may use |
|---|---|
| `:core` | — |
| `:sensor` | `:core` |
| `:fixtures` | `:core` |
| `:cli` | `:core`, `:sensor` |
### Packages do not import each other in a cycle
### Test doubles stay in tests
| rule | values |
|---|---|
| double prefixes | `Fake`, `InMemory`, `Test` |
| modules whose main code is test code | `:fixtures` |

| name | why |
|---|---|
| `InMemoryQueue` | the CLI's queue |
### One type per name
| name | why |
|---|---|
| `Shared` | allowed twice |
"""

CLASS_NUMBERS = itertools.count()


def write(root, path, text):
    full = os.path.join(root, path)
    os.makedirs(os.path.dirname(full), exist_ok=True)
    with open(full, "w", encoding="utf-8") as f:
        f.write(textwrap.dedent(text))


def kotlin(package, *imports, declares=None):
    """A Kotlin file of [package] with [imports], declaring [declares] (a class of a name no other file has by default)."""
    body = declares if declares is not None else f"class X{next(CLASS_NUMBERS)}\n"
    return f"package {package}\n\n" + "".join(f"import {i}\n" for i in imports) + "\n" + body


class ArchitectureTest(unittest.TestCase):
    def project(self, root, cli_build='implementation(project(":sensor"))', extra=()):
        """A four-module project that follows DOC; [extra] adds (path, text) files."""
        write(root, "docs/architecture.md", DOC)
        write(root, "settings.gradle.kts", "".join(f'include(":{m}")\n' for m in ("core", "sensor", "fixtures", "cli")))
        write(root, "core/build.gradle.kts", "dependencies {}\n")
        write(root, "sensor/build.gradle.kts", 'dependencies {\n    api(project(":core"))\n    testImplementation(project(":fixtures"))\n}\n')
        write(root, "fixtures/build.gradle.kts", 'dependencies {\n    api(project(":core"))\n}\n')
        write(root, "cli/build.gradle.kts", "dependencies {\n    " + cli_build + '\n    testImplementation(project(":fixtures"))\n}\n')
        write(root, "core/src/main/kotlin/org/x/core/Icon.kt", kotlin("org.x.core", "java.io.File"))
        write(root, "sensor/src/main/kotlin/org/x/sensor/Decoder.kt", kotlin("org.x.sensor", "org.x.core.Icon", "org.x.sensor.csv.Csv"))
        write(root, "sensor/src/main/kotlin/org/x/sensor/csv/Csv.kt", kotlin("org.x.sensor.csv", "org.x.core.Icon"))
        write(root, "fixtures/src/main/kotlin/org/x/testing/Streams.kt", kotlin("org.x.testing", "org.x.core.Icon"))
        write(root, "cli/src/main/kotlin/org/x/cli/Main.kt", kotlin("org.x.cli", "org.x.cli.common.Console", "org.x.sensor.Decoder"))
        write(root, "cli/src/main/kotlin/org/x/cli/common/Console.kt", kotlin("org.x.cli.common", "org.x.core.Icon"))
        # Tests may use the fixtures.
        write(root, "cli/src/test/kotlin/org/x/cli/MainTest.kt", kotlin("org.x.cli", "org.x.testing.Streams", "org.junit.Test"))
        for path, text in extra:
            write(root, path, text)

    def test_project_followsTheRules(self):
        self.assertEqual([], check(ROOT))

    def test_projectRules_listEveryModuleAndNoMainUseOfTestFixtures(self):
        rules = read_rules(ROOT)
        self.assertEqual(set(), rules.allowed[":haptics-core"])
        self.assertEqual({":haptics-core"}, rules.allowed[":sensor-bridge"])
        self.assertFalse(any(":test-fixtures" in used for used in rules.allowed.values()))

    def test_followingProject_hasNoViolations(self):
        with tempfile.TemporaryDirectory() as root:
            self.project(root)
            self.assertEqual([], check(root))

    def test_forbiddenImport_isReportedWithTheFile(self):
        with tempfile.TemporaryDirectory() as root:
            self.project(root, extra=[("cli/src/main/kotlin/org/x/cli/Bench.kt", kotlin("org.x.cli", "org.x.testing.Streams"))])
            self.assertEqual(
                ["cli/src/main/kotlin/org/x/cli/Bench.kt: imports org.x.testing.Streams from :fixtures, "
                 "which docs/architecture.md does not allow for :cli"],
                check(root),
            )

    def test_importAgainstTheFlow_isReported(self):
        with tempfile.TemporaryDirectory() as root:
            self.project(root, extra=[("core/src/main/kotlin/org/x/core/Back.kt", kotlin("org.x.core", "org.x.sensor.Decoder"))])
            self.assertEqual(1, len(check(root)))
            self.assertIn("imports org.x.sensor.Decoder from :sensor", check(root)[0])

    def test_fullyQualifiedUseInCode_isReported_inCommentsAndStringsIsNot(self):
        with tempfile.TemporaryDirectory() as root:
            text = (
                "package org.x.cli.common\n\n"
                "/** Called by [org.x.cli.Main]; see \"org.x.cli.Main\". */\n"
                "fun run(console: org.x.cli.Main) = \"org.x.cli.Main\" // org.x.cli.Main\n"
            )
            self.project(root, extra=[("cli/src/main/kotlin/org/x/cli/common/Run.kt", text)])
            self.assertEqual([":cli: packages import each other in a cycle: org.x.cli, org.x.cli.common"], check(root))

    def test_forbiddenMainBuildDependency_isReported(self):
        with tempfile.TemporaryDirectory() as root:
            self.project(root, cli_build='implementation(project(":sensor"))\n    implementation(project(":fixtures")) // bench data')
            self.assertEqual(
                ["cli/build.gradle.kts: main code depends on :fixtures, which docs/architecture.md does not allow"],
                [v.replace(os.sep, "/") for v in check(root)],
            )

    def test_rootAndSubpackageCycle_isReported(self):
        with tempfile.TemporaryDirectory() as root:
            self.project(root, extra=[("cli/src/main/kotlin/org/x/cli/common/Args.kt", kotlin("org.x.cli.common", "org.x.cli.Main"))])
            self.assertEqual([":cli: packages import each other in a cycle: org.x.cli, org.x.cli.common"], check(root))

    def test_cycleInAnyModule_isReported_oneLineNamingItsPackages(self):
        with tempfile.TemporaryDirectory() as root:
            self.project(root, extra=[
                ("sensor/src/main/kotlin/org/x/sensor/csv/Csv.kt", kotlin("org.x.sensor.csv", "org.x.sensor.lucid.Lucid")),
                ("sensor/src/main/kotlin/org/x/sensor/lucid/Lucid.kt", kotlin("org.x.sensor.lucid", "org.x.sensor.Decoder")),
            ])
            self.assertEqual([":sensor: packages import each other in a cycle: org.x.sensor, org.x.sensor.csv, org.x.sensor.lucid"], check(root))

    def test_twoCycles_areTwoViolations(self):
        with tempfile.TemporaryDirectory() as root:
            self.project(root, extra=[
                ("sensor/src/main/kotlin/org/x/sensor/csv/Csv.kt", kotlin("org.x.sensor.csv", "org.x.sensor.Decoder")),
                ("cli/src/main/kotlin/org/x/cli/common/Args.kt", kotlin("org.x.cli.common", "org.x.cli.Main")),
            ])
            self.assertEqual(
                [":sensor: packages import each other in a cycle: org.x.sensor, org.x.sensor.csv",
                 ":cli: packages import each other in a cycle: org.x.cli, org.x.cli.common"],
                check(root),
            )

    def test_featureImportingASiblingFeature_isReported_sharedPackagesAndItsOwnSubpackagesAreNot(self):
        with tempfile.TemporaryDirectory() as root:
            self.project(root, extra=[
                ("cli/src/main/kotlin/org/x/cli/feature/chat/Chat.kt", kotlin("org.x.cli.feature.chat", "org.x.cli.feature.chat.parts.Row", "org.x.cli.common.Console")),
                ("cli/src/main/kotlin/org/x/cli/feature/chat/parts/Row.kt", kotlin("org.x.cli.feature.chat.parts", "org.x.cli.feature.editor.Editor")),
                ("cli/src/main/kotlin/org/x/cli/feature/editor/Editor.kt", kotlin("org.x.cli.feature.editor", "org.x.cli.common.Console")),
                ("cli/src/main/kotlin/org/x/cli/nav/Nav.kt", kotlin("org.x.cli.nav", "org.x.cli.feature.chat.Chat", "org.x.cli.feature.editor.Editor")),
            ])
            self.assertEqual(
                ["cli/src/main/kotlin/org/x/cli/feature/chat/parts/Row.kt: feature org.x.cli.feature.chat imports "
                 "org.x.cli.feature.editor.Editor from feature org.x.cli.feature.editor; features do not import each other"],
                [v.replace(os.sep, "/") for v in check(root)],
            )

    def test_featureUsingTheContainer_isReported_theNavigationMayUseIt(self):
        with tempfile.TemporaryDirectory() as root:
            self.project(root, extra=[
                ("cli/src/main/kotlin/org/x/cli/di/Container.kt", kotlin("org.x.cli.di", "org.x.cli.common.Console")),
                ("cli/src/main/kotlin/org/x/cli/feature/chat/Chat.kt", kotlin("org.x.cli.feature.chat", "org.x.cli.di.Container")),
                ("cli/src/main/kotlin/org/x/cli/nav/Nav.kt", kotlin("org.x.cli.nav", "org.x.cli.di.Container", "org.x.cli.feature.chat.Chat")),
            ])
            self.assertEqual(
                ["cli/src/main/kotlin/org/x/cli/feature/chat/Chat.kt: feature org.x.cli.feature.chat imports "
                 "org.x.cli.di.Container; a route takes what it uses, not the container"],
                [v.replace(os.sep, "/") for v in check(root)],
            )

    def test_androidGeneratedClassesOfTheNamespace_closeNoCycle_aClassNamedLikeThemDoes(self):
        with tempfile.TemporaryDirectory() as root:
            self.project(root, extra=[
                # R and BuildConfig are generated in org.x.cli and import nothing: using them from below is no cycle.
                ("cli/src/main/kotlin/org/x/cli/common/Strings.kt", kotlin("org.x.cli.common", "org.x.cli.R", "org.x.cli.BuildConfig")),
                ("cli/src/main/kotlin/org/x/cli/common/Icons.kt",
                 "package org.x.cli.common\n\nval icon = org.x.cli.R.drawable.icon\n"),
            ])
            with open(os.path.join(root, "cli", "build.gradle.kts"), "a", encoding="utf-8") as f:
                f.write('android {\n    namespace = "org.x.cli"\n}\n')
            self.assertEqual([], check(root))
            # A class of the root package whose name only starts with R is an ordinary class.
            write(root, "cli/src/main/kotlin/org/x/cli/Results.kt", kotlin("org.x.cli"))
            write(root, "cli/src/main/kotlin/org/x/cli/common/Table.kt", kotlin("org.x.cli.common", "org.x.cli.Results"))
            self.assertEqual([":cli: packages import each other in a cycle: org.x.cli, org.x.cli.common"], check(root))

    def test_generatedClassesOfAPlainJvmModule_areOrdinaryNames(self):
        with tempfile.TemporaryDirectory() as root:
            self.project(root, extra=[("cli/src/main/kotlin/org/x/cli/common/Strings.kt", kotlin("org.x.cli.common", "org.x.cli.R"))])
            self.assertEqual([":cli: packages import each other in a cycle: org.x.cli, org.x.cli.common"], check(root))

    def test_moduleMissingFromTheTable_isReported(self):
        with tempfile.TemporaryDirectory() as root:
            self.project(root)
            with open(os.path.join(root, "settings.gradle.kts"), "a", encoding="utf-8") as f:
                f.write('include(":extra")\n')
            write(root, "extra/build.gradle.kts", "dependencies {}\n")
            self.assertEqual([":extra: not in docs/architecture.md's 'Who may use whom' table"], check(root))

    def test_projectRules_nameTheDoublePrefixesAndTheTestCodeModules(self):
        rules = read_rules(ROOT)
        self.assertIn("Fake", rules.double_prefixes)
        self.assertIn("InMemory", rules.double_prefixes)
        self.assertIn("Test", rules.double_prefixes)
        self.assertEqual({":test-fixtures", ":test-fixtures:android", ":device-check"}, rules.test_code_modules)

    def test_fixtureRules_readFromTheirSections(self):
        with tempfile.TemporaryDirectory() as root:
            self.project(root)
            rules = read_rules(root)
            self.assertEqual(("Fake", "InMemory", "Test"), rules.double_prefixes)
            self.assertEqual({":fixtures"}, rules.test_code_modules)
            self.assertEqual({"InMemoryQueue"}, rules.doubles_allowed)
            self.assertEqual({"Shared"}, rules.shared_names_allowed)

    def test_doubleInMainCode_isReportedWithItsFileAndModule(self):
        with tempfile.TemporaryDirectory() as root:
            fake = "/** A port for tests. */\n@Suppress(\"unused\")\npublic class FakePort : Port {\n    class Inner\n}\n"
            self.project(root, extra=[("sensor/src/main/kotlin/org/x/sensor/FakePort.kt", kotlin("org.x.sensor", declares=fake))])
            self.assertEqual(
                ["sensor/src/main/kotlin/org/x/sensor/FakePort.kt: test double FakePort in the main code of :sensor: "
                 "move it to its tests or :test-fixtures"],
                check(root),
            )

    def test_everyKindOfDeclaration_isSeen(self):
        with tempfile.TemporaryDirectory() as root:
            declarations = "internal data class InMemoryStore(val x: Int)\nsealed interface TestState\nprivate object FakeClock\nenum class Testament { A }\n"
            self.project(root, extra=[("cli/src/main/kotlin/org/x/cli/Doubles.kt", kotlin("org.x.cli", declares=declarations))])
            self.assertEqual(
                ["InMemoryStore", "TestState", "FakeClock"],
                [v.split("test double ")[1].split(" ")[0] for v in check(root)],
            )

    def test_doubleInTestSources_inATestCodeModule_orAllowed_isNot(self):
        with tempfile.TemporaryDirectory() as root:
            self.project(root, extra=[
                ("sensor/src/test/kotlin/org/x/sensor/FakePort.kt", kotlin("org.x.sensor", declares="class FakePort\n")),
                ("fixtures/src/main/kotlin/org/x/testing/TestIcons.kt", kotlin("org.x.testing", declares="object TestIcons\n")),
                ("cli/src/main/kotlin/org/x/cli/Queue.kt", kotlin("org.x.cli", declares="class InMemoryQueue\n")),
                # Nested types are not top-level names of the module.
                ("cli/src/main/kotlin/org/x/cli/Outer.kt", kotlin("org.x.cli", declares="class Outer {\n    class FakeInner\n}\n")),
            ])
            self.assertEqual([], check(root))

    def test_sameTypeNameInTwoModules_isReportedOnce_namingBothFiles(self):
        with tempfile.TemporaryDirectory() as root:
            self.project(root, extra=[
                ("core/src/main/kotlin/org/x/core/State.kt", kotlin("org.x.core", declares="enum class ConnectionState { UP }\n")),
                ("sensor/src/main/kotlin/org/x/sensor/State.kt", kotlin("org.x.sensor", declares="private sealed interface ConnectionState\n")),
            ])
            self.assertEqual(
                ["2 types of main code named ConnectionState: core/src/main/kotlin/org/x/core/State.kt, "
                 "sensor/src/main/kotlin/org/x/sensor/State.kt; give each a name of its own"],
                check(root),
            )

    def test_sameTypeNameAllowed_orInTestsOrNested_isNot(self):
        with tempfile.TemporaryDirectory() as root:
            self.project(root, extra=[
                ("core/src/main/kotlin/org/x/core/Shared.kt", kotlin("org.x.core", declares="object Shared\n")),
                ("sensor/src/main/kotlin/org/x/sensor/Shared.kt", kotlin("org.x.sensor", declares="object Shared\n")),
                ("core/src/main/kotlin/org/x/core/Csv.kt", kotlin("org.x.core", declares="object Csv\n")),
                ("cli/src/test/kotlin/org/x/cli/Csv.kt", kotlin("org.x.cli", declares="object Csv\n")),
                ("cli/src/main/kotlin/org/x/cli/Table.kt", kotlin("org.x.cli", declares="class Table {\n    object Csv\n}\n")),
            ])
            self.assertEqual([], check(root))

    def test_cycles_findsOnlyComponentsOfSeveralPackages(self):
        graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}, "e": set()}
        self.assertEqual([{"a", "b", "c"}], cycles(graph))
        self.assertEqual([], cycles({"a": {"b"}, "b": set()}))


if __name__ == "__main__":
    unittest.main()
