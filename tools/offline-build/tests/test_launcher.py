"""Tests of ./hapticon's staleness check: it calls the build exactly when a companion input changed."""
import os
import shutil
import stat
import subprocess
import tempfile
import textwrap
import time
import unittest

from hapticon_build.__main__ import companion_inputs
from hapticon_build.project import load_project

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))

# Stands in for ./build: logs each call and writes what `./build companion` writes.
FAKE_BUILD = """#!/usr/bin/env bash
set -e
cd "$(dirname "$0")"
echo "$*" >>build.log
mkdir -p out/companion
printf 'classes\\norg.demo.MainKt\\n' >out/companion/runtime-classpath.txt
printf 'settings.gradle.kts\\ncompanion/build.gradle.kts\\ncompanion/src/main\\n' >out/companion/inputs.txt
"""

# Stands in for java: prints the main class and arguments it was given.
FAKE_JAVA = """#!/usr/bin/env bash
echo "java ${@: -2}"
"""


def write(root, path, text, mode=None):
    full = os.path.join(root, path)
    os.makedirs(os.path.dirname(full), exist_ok=True)
    with open(full, "w") as f:
        f.write(text)
    if mode:
        os.chmod(full, os.stat(full).st_mode | mode)


class LauncherTest(unittest.TestCase):
    def setUp(self):
        self.root = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, self.root)
        shutil.copy(os.path.join(REPO, "hapticon"), self.root)
        write(self.root, "build", FAKE_BUILD, stat.S_IXUSR)
        write(self.root, "bin/java", FAKE_JAVA, stat.S_IXUSR)
        write(self.root, "settings.gradle.kts", 'include(":companion")\n')
        write(self.root, "companion/build.gradle.kts", "plugins {}\n")
        write(self.root, "companion/src/main/kotlin/Main.kt", "fun main() {}\n")

    def run_hapticon(self):
        env = dict(os.environ, PATH=os.path.join(self.root, "bin") + os.pathsep + os.environ["PATH"])
        p = subprocess.run([os.path.join(self.root, "hapticon"), "icons"], env=env, text=True,
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        self.assertEqual(0, p.returncode, p.stderr)
        self.assertEqual("java org.demo.MainKt icons\n", p.stdout)

    def builds(self):
        path = os.path.join(self.root, "build.log")
        if not os.path.exists(path):
            return []
        with open(path) as f:
            return f.read().splitlines()

    def assert_rebuilds(self, change):
        self.run_hapticon()
        before = len(self.builds())
        self.run_hapticon()
        self.assertEqual(before, len(self.builds()), "an unchanged tree must not call the build")
        time.sleep(0.01)  # a distinct mtime even on coarse clocks
        change()
        self.run_hapticon()
        self.assertEqual(before + 1, len(self.builds()), "a changed input must call the build")
        self.run_hapticon()
        self.assertEqual(before + 1, len(self.builds()), "after rebuilding, the same tree must not call it again")

    def test_hapticon_firstCall_buildsThenRunsJava(self):
        self.run_hapticon()
        self.assertEqual(["--quiet companion"], self.builds())

    def test_hapticon_unchangedInputs_runsJavaWithoutBuilding(self):
        self.run_hapticon()
        for _ in range(3):
            self.run_hapticon()
        self.assertEqual(1, len(self.builds()))

    def test_hapticon_sourceEdited_rebuilds(self):
        self.assert_rebuilds(lambda: write(self.root, "companion/src/main/kotlin/Main.kt", "fun main() { }\n"))

    def test_hapticon_sourceTouchedSameSize_rebuilds(self):
        path = os.path.join(self.root, "companion/src/main/kotlin/Main.kt")
        self.assert_rebuilds(lambda: os.utime(path, ns=(time.time_ns(), time.time_ns() + 5_000_000_000)))

    def test_hapticon_sourceAdded_rebuilds(self):
        self.assert_rebuilds(lambda: write(self.root, "companion/src/main/kotlin/More.kt", "val x = 1\n"))

    def test_hapticon_sourceDeleted_rebuilds(self):
        write(self.root, "companion/src/main/kotlin/More.kt", "val x = 1\n")
        self.assert_rebuilds(lambda: os.remove(os.path.join(self.root, "companion/src/main/kotlin/More.kt")))

    def test_hapticon_buildFileEdited_rebuilds(self):
        self.assert_rebuilds(lambda: write(self.root, "companion/build.gradle.kts", "plugins { }\n"))

    def test_hapticon_settingsEdited_rebuilds(self):
        self.assert_rebuilds(lambda: write(self.root, "settings.gradle.kts", 'include(":companion")\ninclude(":x")\n'))

    def test_hapticon_outDeleted_rebuilds(self):
        self.assert_rebuilds(lambda: shutil.rmtree(os.path.join(self.root, "out")))

    def test_hapticon_failedBuild_recordsNoFingerprintAndRetries(self):
        self.run_hapticon()
        write(self.root, "companion/src/main/kotlin/Main.kt", "broken\n")
        write(self.root, "build", "#!/usr/bin/env bash\necho failed >>\"$(dirname \"$0\")/build.log\"\nexit 1\n")
        env = dict(os.environ, PATH=os.path.join(self.root, "bin") + os.pathsep + os.environ["PATH"])
        for _ in range(2):
            p = subprocess.run([os.path.join(self.root, "hapticon"), "icons"], env=env, capture_output=True)
            self.assertEqual(1, p.returncode)
        self.assertEqual(["--quiet companion", "failed", "failed"], self.builds())


class CompanionInputsTest(unittest.TestCase):
    def test_companionInputs_listsRuntimeModulesNotTestOnlyOnes(self):
        root = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, root)
        write(root, "gradle/libs.versions.toml", "[versions]\n[libraries]\n[plugins]\n")
        write(root, "settings.gradle.kts", 'include(":core")\ninclude(":extra")\ninclude(":companion")\ninclude(":fixtures")\n')
        for name in ("core", "extra", "fixtures"):
            write(root, f"{name}/build.gradle.kts", "plugins {\n}\n")
        write(root, "companion/build.gradle.kts", textwrap.dedent("""
            plugins {
            }
            dependencies {
                implementation(project(":core"))
                testImplementation(project(":fixtures"))
            }
        """))
        write(root, "core/build.gradle.kts", 'plugins {\n}\ndependencies {\n    api(project(":extra"))\n}\n')
        inputs = companion_inputs(load_project(root))
        for name in ("companion", "core", "extra"):
            self.assertIn(f"{name}/src/main", inputs)
            self.assertIn(f"{name}/build.gradle.kts", inputs)
        self.assertNotIn("fixtures/src/main", inputs)
        self.assertIn("settings.gradle.kts", inputs)
        self.assertIn("gradle/libs.versions.toml", inputs)
        self.assertIn("tools/offline-build/hapticon_build", inputs)

    def test_companionInputs_listsTheConventionPluginsItsModulesApply(self):
        root = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, root)
        write(root, "gradle/libs.versions.toml", '[versions]\n[libraries]\n[plugins]\ndemo-library = { id = "demo.library" }\n')
        write(root, "settings.gradle.kts", 'pluginManagement {\n    includeBuild("build-logic")\n}\n'
              'include(":core")\ninclude(":companion")\ninclude(":fixtures")\n')
        write(root, "build-logic/src/main/kotlin/demo.library.gradle.kts", "plugins {\n}\n")
        write(root, "build-logic/src/main/kotlin/demo.unused.gradle.kts", "plugins {\n}\n")
        write(root, "core/build.gradle.kts", "plugins {\n    alias(libs.plugins.demo.library)\n}\n")
        write(root, "fixtures/build.gradle.kts", "plugins {\n}\n")
        write(root, "companion/build.gradle.kts", 'dependencies {\n    implementation(project(":core"))\n}\n')
        inputs = companion_inputs(load_project(root))
        self.assertIn("build-logic/src/main/kotlin/demo.library.gradle.kts", inputs)
        self.assertNotIn("build-logic/src/main/kotlin/demo.unused.gradle.kts", inputs)


if __name__ == "__main__":
    unittest.main()


class RunDemoTest(unittest.TestCase):
    """`./build demo` (run_demo): the companion's demo runs while the APK is built, its output then the APK's line."""

    def setUp(self):
        from types import SimpleNamespace
        from unittest import mock
        from hapticon_build.ui import StageTimes
        self.root = tempfile.mkdtemp()
        java = os.path.join(self.root, "java")  # stands in for java running the companion: prints its arguments
        write(self.root, "java", '#!/usr/bin/env bash\necho "hapticon ${@: -3}"\nexit ${FAKE_DEMO_EXIT:-0}\n',
              stat.S_IXUSR)
        self.apk = os.path.join(self.root, "out", "app", "hapticon-debug.apk")
        write(self.root, "out/app/hapticon-debug.apk", "x" * 2_500_000)
        companion = SimpleNamespace(main_class="org.hapticon.companion.MainKt")
        self.build = SimpleNamespace(root=self.root, out=os.path.join(self.root, "out"), tools=SimpleNamespace(java=java),
                                     project=SimpleNamespace(module=lambda path: companion), kotlinc=mock.Mock(),
                                     stage_times=StageTimes(os.path.join(self.root, ".build-cache", "st.json")))
        self.seen_during_assemble = []
        test = self

        class FakeApp:
            def __init__(self, build, module):
                pass

            def start_library_dex(self):
                pass

            def assemble(self):
                log = os.path.join(test.root, "out", "demo.log")
                for _ in range(100):  # the demo is already running: its output arrives while the APK is built
                    if os.path.exists(log) and open(log).read():
                        break
                    time.sleep(0.05)
                test.seen_during_assemble.append(open(log).read())
                return test.apk
        self.patches = [mock.patch("hapticon_build.android.AndroidApp", FakeApp),
                        mock.patch("hapticon_build.__main__.companion_classpath", return_value=["classes"]),
                        mock.patch("hapticon_build.__main__.app_module", return_value=None)]
        for p in self.patches:
            p.start()
        self.addCleanup(lambda: [p.stop() for p in self.patches])

    def run_demo(self) -> str:
        import contextlib
        import io
        from hapticon_build.__main__ import run_demo
        out = io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
            run_demo(self.build)
        return out.getvalue()

    def test_runDemo_demoRunsDuringTheApkBuild_thenItsOutputAndTheApkLine(self):
        printed = self.run_demo()
        out_demo = os.path.join(self.root, "out", "demo")
        self.assertEqual([f"hapticon demo --out {out_demo}\n"], self.seen_during_assemble)
        self.assertEqual(f"hapticon demo --out {out_demo}\nAPK: {self.apk} (2500000 bytes, 2.5 MB)\n", printed)
        self.assertIn("companion demo", self.build.stage_times.times)

    def test_runDemo_demoFails_failsNamingItsExitAndLog(self):
        from unittest import mock
        from hapticon_build.errors import BuildError
        with mock.patch.dict(os.environ, {"FAKE_DEMO_EXIT": "3"}), self.assertRaises(BuildError) as e:
            self.run_demo()
        self.assertEqual("hapticon demo exited 3 (out/demo.log)", str(e.exception))
        self.assertNotIn("companion demo", self.build.stage_times.times)
