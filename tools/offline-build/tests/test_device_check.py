"""Tests of the device check's build side: the test module, its instrumentation manifest, and `./build device-check`
without a phone (adb output and `am instrument -r` output are read from recorded samples)."""
import io
import os
import stat
import tempfile
import textwrap
import unittest
import xml.etree.ElementTree as ET
from types import SimpleNamespace
from unittest import mock

from hapticon_build import device_check
from hapticon_build.builder import Build
from hapticon_build.device_check import attached, parse_instrumentation, report_line
from hapticon_build.errors import BuildError
from hapticon_build.instrumentation import instrumentation_of, with_instrumentation
from hapticon_build.project import load_project
from tests.test_build_tool import write

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
ANDROID = "{http://schemas.android.com/apk/res/android}"
FIXTURES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fixtures", "device-check")

CATALOG = """
[versions]
kotlin = "2.4.21"
agp = "9.4.1"
[libraries]
kotlin-stdlib = { module = "org.jetbrains.kotlin:kotlin-stdlib", version.ref = "kotlin" }
[plugins]
android-application = { id = "com.android.application", version.ref = "agp" }
android-test = { id = "com.android.test", version.ref = "agp" }
"""


def fixture(name):
    with open(os.path.join(FIXTURES, name), encoding="utf-8") as f:
        return f.read()


class TestModuleTest(unittest.TestCase):
    def setUp(self):
        self.root = tempfile.mkdtemp()
        write(self.root, "gradle/libs.versions.toml", CATALOG)
        write(self.root, "settings.gradle.kts", 'rootProject.name = "demo"\ninclude(":app")\ninclude(":check")\n')
        write(self.root, "app/build.gradle.kts", """
            plugins { alias(libs.plugins.android.application) }
            android { namespace = "org.demo"; compileSdk = 37; defaultConfig { minSdk = 26; targetSdk = 35; applicationId = "org.demo.app" } }
        """)

    def check_module(self, android_extra='experimentalProperties["android.experimental.self-instrumenting"] = true'):
        write(self.root, "check/build.gradle.kts", f"""
            plugins {{
                alias(libs.plugins.android.test)
            }}
            android {{
                namespace = "org.demo.check"
                compileSdk = 37
                targetProjectPath = ":app"
                defaultConfig {{
                    minSdk = 31
                    targetSdk = 35
                    testInstrumentationRunner = "androidx.test.runner.AndroidJUnitRunner"
                }}
                {android_extra}
            }}
        """)
        return load_project(self.root)

    def test_load_project_testModule_readsTargetRunnerAndSelfInstrumenting(self):
        module = self.check_module().module(":check")
        self.assertTrue(module.is_android_test)
        self.assertTrue(module.is_android)
        self.assertFalse(module.is_android_app)
        self.assertEqual(":app", module.android["targetProjectPath"])
        self.assertEqual("androidx.test.runner.AndroidJUnitRunner", module.android["testInstrumentationRunner"])
        self.assertEqual("true", module.android["android.experimental.self-instrumenting"])
        self.assertEqual("31", module.android["minSdk"])

    def test_load_project_testModuleWithoutRunner_failsNamingIt(self):
        write(self.root, "check/build.gradle.kts", """
            plugins { alias(libs.plugins.android.test) }
            android { namespace = "org.demo.check"; compileSdk = 37; targetProjectPath = ":app"; defaultConfig { minSdk = 31; targetSdk = 35 } }
        """)
        with self.assertRaisesRegex(BuildError, "testInstrumentationRunner"):
            load_project(self.root)

    def test_instrumentationApk_notSelfInstrumenting_refusedWithTheReason(self):
        from hapticon_build.instrumentation import InstrumentationApk
        project = self.check_module(android_extra="")
        with self.assertRaisesRegex(BuildError, "self-instrumenting"):
            InstrumentationApk(Build(project), project.module(":check"))

    def test_buildTest_testModule_runsAndCompilesNothing(self):
        # `./build test` must not compile a test module's sources for the JVM: they run on a phone only.
        project = self.check_module()
        build = Build(project)
        with mock.patch.object(build, "compile_module", side_effect=AssertionError("compiled")):
            result = build.test_module(project.module(":check"))
        self.assertEqual((0, 0, 0, False), (result.passed, result.failed, result.skipped, result.crashed))

    def test_load_project_thisRepository_deviceCheckIsASelfInstrumentingTestOfTheApp(self):
        project = load_project(REPO)
        module = project.module(":device-check")
        self.assertTrue(module.is_android_test)
        self.assertEqual(":app", module.android["targetProjectPath"])
        self.assertEqual("true", module.android["android.experimental.self-instrumenting"])
        self.assertEqual("androidx.test.runner.AndroidJUnitRunner", module.android["testInstrumentationRunner"])
        runtime = {str(d.library).rsplit(":", 1)[0] for d in module.deps("implementation") if d.library}
        self.assertLessEqual({"androidx.test:runner", "androidx.test.ext:junit", "androidx.test.uiautomator:uiautomator"}, runtime)


class ManifestTest(unittest.TestCase):
    def test_withInstrumentation_addsAgpsElementNamingRunnerAndTarget(self):
        manifest = with_instrumentation(
            '<manifest xmlns:android="http://schemas.android.com/apk/res/android">\n'
            '    <uses-permission android:name="android.permission.INTERNET" />\n</manifest>\n',
            "androidx.test.runner.AndroidJUnitRunner", "org.hapticon.devicecheck", "Tests for org.hapticon.app")
        root = ET.fromstring(manifest)
        element = root.find("instrumentation")
        self.assertEqual("androidx.test.runner.AndroidJUnitRunner", element.get(ANDROID + "name"))
        self.assertEqual("org.hapticon.devicecheck", element.get(ANDROID + "targetPackage"))
        self.assertEqual("false", element.get(ANDROID + "handleProfiling"))
        self.assertEqual("false", element.get(ANDROID + "functionalTest"))
        self.assertEqual("Tests for org.hapticon.app", element.get(ANDROID + "label"))
        self.assertIsNotNone(root.find("uses-permission"))

    def test_withInstrumentation_selfClosingManifest_opensIt(self):
        manifest = with_instrumentation('<manifest xmlns:android="http://schemas.android.com/apk/res/android" />',
                                        "r.Runner", "p.q", "Tests")
        self.assertEqual("p.q", ET.fromstring(manifest).find("instrumentation").get(ANDROID + "targetPackage"))

    def test_withInstrumentation_manifestDeclaresOne_fails(self):
        with self.assertRaisesRegex(BuildError, "must not declare <instrumentation>"):
            with_instrumentation('<manifest><instrumentation /></manifest>', "r.Runner", "p.q", "Tests")

    def test_withInstrumentation_commentNamingTheElement_notADeclaration(self):
        manifest = with_instrumentation('<!-- the build adds the <instrumentation> element -->\n'
                                        '<manifest xmlns:android="http://schemas.android.com/apk/res/android">\n</manifest>\n',
                                        "r.Runner", "p.q", "Tests")
        self.assertEqual(1, manifest.count("<instrumentation "))

    def test_instrumentationOf_aapt2Xmltree_readsTheElementsAttributes(self):
        element = instrumentation_of(fixture("xmltree.txt"))
        self.assertEqual("androidx.test.runner.AndroidJUnitRunner", element["name"])
        self.assertEqual("org.hapticon.devicecheck", element["targetPackage"])
        self.assertEqual("Tests for org.hapticon.app", element["label"])

    def test_instrumentationOf_noElement_none(self):
        self.assertIsNone(instrumentation_of("N: android=http://schemas.android.com/apk/res/android\n  E: manifest (line=2)\n"))


class AdbOutputTest(unittest.TestCase):
    def test_attached_readyAndOthersWithTheirState(self):
        ready, other = attached("List of devices attached\n0A1B2C3D\tdevice\nemulator-5554\tunauthorized\n\n")
        self.assertEqual(["0A1B2C3D"], ready)
        self.assertEqual(["emulator-5554 unauthorized"], other)

    def test_attached_none(self):
        self.assertEqual(([], []), attached("List of devices attached\n\n"))

    def test_parseInstrumentation_recordedRun_eachTestWithItsOutcomeMessageAndNotes(self):
        ended = []
        outcomes, result = parse_instrumentation(io.StringIO(fixture("am-instrument-r.txt")), ended.append)
        self.assertEqual(["passed", "failed", "skipped"], [o.status for o in outcomes])
        self.assertEqual(outcomes, ended)  # reported as each one ends
        first, second, third = outcomes
        self.assertEqual("ReceivedKnockTest#swipedAwayScreenOff_knockIsNotifiedThenFeltAsCommunicationRequest_senderGetsFelt", first.name)
        self.assertEqual(["knock: COMMUNICATION_REQUEST, finished, 560 ms, 26 ms after its notification; felt 1204 ms after sending; "
                          "app process state 4"], first.notes)
        self.assertEqual("", first.message)
        self.assertEqual("java.lang.AssertionError: the knock's vibration usage (app uid 10234 process state 12; its recent "
                         "vibrations: []) expected:<COMMUNICATION_REQUEST> but was:<UNKNOWN>", second.message)
        self.assertIn("Tests run: 3,  Failures: 1", result)
        self.assertIn("FAIL ReceivedKnockTest#conversationOpenScreenOff_knockStillFeltAndNotified_noRead", report_line(second))
        self.assertIn("expected:<COMMUNICATION_REQUEST> but was:<UNKNOWN>", report_line(second))

    def test_parseInstrumentation_processCrashMidTest_failsThatTest(self):
        outcomes, result = parse_instrumentation(io.StringIO(textwrap.dedent("""\
            INSTRUMENTATION_STATUS: class=org.hapticon.devicecheck.ReceivedKnockTest
            INSTRUMENTATION_STATUS: test=doNotDisturb_knockArrivesButNothingVibrates_noFelt
            INSTRUMENTATION_STATUS_CODE: 1
            INSTRUMENTATION_RESULT: shortMsg=Process crashed.
            INSTRUMENTATION_CODE: 0
        """)))
        self.assertEqual("failed", outcomes[0].status)
        self.assertIn("shortMsg=Process crashed.", result)


class TestsOptionTest(unittest.TestCase):
    def test_tests_classOrMethod_qualifiedWithTheSuitesPackage(self):
        self.assertIsNone(device_check.tests_option([]))
        self.assertEqual("org.hapticon.devicecheck.ReceivedKnockTest#doNotDisturb_knockArrivesButNothingVibrates_noFelt",
                         device_check.tests_option(["--tests", "ReceivedKnockTest#doNotDisturb_knockArrivesButNothingVibrates_noFelt"]))
        self.assertEqual("org.x.OtherTest", device_check.tests_option(["--tests", "org.x.OtherTest"]))

    def test_tests_anythingElse_failsNamingTheOption(self):
        for rest in (["--tests"], ["--device", "x"], ["--tests", "A", "B"]):
            with self.assertRaisesRegex(BuildError, "only --tests CLASS"):
                device_check.tests_option(rest)


class NoDeviceTest(unittest.TestCase):
    """`./build device-check` where this machine is: the APKs built, no phone to run them on."""

    def setUp(self):
        self.root = tempfile.mkdtemp()
        self.build = SimpleNamespace(root=self.root, project=None, cache=os.path.join(self.root, ".build-cache"))
        self.tester = SimpleNamespace(min_sdk="31", application_id="org.hapticon.devicecheck", runner="r.Runner")
        self.apps = (os.path.join(self.root, "out", "app", "hapticon-debug.apk"),
                     os.path.join(self.root, "out", "device-check", "hapticon-device-check.apk"))

    def run_check(self, adb):
        out = io.StringIO()
        with mock.patch.dict(os.environ, {}), mock.patch.object(device_check, "adb_server_running", return_value=True):
            os.environ.pop("ANDROID_SERIAL", None)
            code = device_check.run(self.build, [], *self.apps, self.tester, out, find=lambda cache: adb)
        return code, out.getvalue()

    def fake_adb(self, devices_output):
        adb = os.path.join(tempfile.mkdtemp(), "adb")
        with open(adb, "w") as f:
            f.write("#!/bin/sh\nprintf '%s'\n" % devices_output.replace("\n", "\\n").replace("\t", "\\t"))
        os.chmod(adb, os.stat(adb).st_mode | stat.S_IXUSR)
        return adb

    def test_noAdb_theReasonInOneLine_exit0(self):
        code, output = self.run_check((None, "adb not found: not on PATH"))
        self.assertEqual(0, code)
        self.assertEqual("device-check: adb not found: not on PATH; skipped\n", output)

    def test_adbListsNoDevice_oneLine_exit0(self):
        code, output = self.run_check((self.fake_adb("List of devices attached\n\n"), ""))
        self.assertEqual(0, code)
        self.assertEqual("device-check: no device attached (adb devices lists none); skipped\n", output)

    def test_adbStartsItsServerFirst_daemonLinesAreNoDevices(self):
        ready, other = attached("* daemon not running; starting now at tcp:5037\n* daemon started successfully\n"
                                "List of devices attached\n\n")
        self.assertEqual(([], []), (ready, other))

    def test_adbListsOnlyAnUnauthorizedPhone_saysSo_exit0(self):
        code, output = self.run_check((self.fake_adb("List of devices attached\nR58M123\tunauthorized\n\n"), ""))
        self.assertEqual(0, code)
        self.assertEqual("device-check: no device attached (adb devices lists none ready: R58M123 unauthorized); skipped\n",
                         output)

    def test_run_serverNotRunningBefore_stopsTheOneItStarted(self):
        log = os.path.join(self.root, "adb.log")
        adb = os.path.join(tempfile.mkdtemp(), "adb")
        with open(adb, "w") as f:
            f.write(f"#!/bin/sh\necho \"$@\" >> {log}\nprintf 'List of devices attached\\n\\n'\n")
        os.chmod(adb, 0o755)
        with mock.patch.object(device_check, "adb_server_running", return_value=False):
            device_check.run(self.build, [], *self.apps, self.tester, io.StringIO(), find=lambda cache: (adb, ""))
        self.assertEqual("devices\nkill-server\n", open(log).read())


class PhoneRunTest(unittest.TestCase):
    """`./build device-check` with a phone, the phone played by a fake adb that logs each call and answers it as a phone
    with a Hapticon account and Do Not Disturb off would; `am instrument` answers with a recorded run."""

    CHAT_XML = "<?xml version='1.0' ?><map><string name='user'>ana</string></map>"
    FAKE_ADB = textwrap.dedent("""\
        #!/bin/sh
        case "$*" in *"cat >"*) stdin=" <<$(cat | wc -c)" ;; *) stdin="" ;; esac
        echo "$*$stdin" >> "$FAKE_ADB_LOG"
        [ "$1" = "-s" ] && shift 2
        case "$*" in
            devices) printf 'List of devices attached\\nR58M123\\tdevice\\n\\n' ;;
            "shell getprop ro.build.version.sdk") echo 35 ;;
            "shell getprop ro.product.model") echo "Pixel 7" ;;
            "shell getprop ro.build.version.release") echo 15 ;;
            "shell settings get global zen_mode")  # as it was before the suite, then as the suite left it
                if [ -e "$FAKE_ADB_LOG.zen" ]; then echo "$FAKE_ZEN_AFTER"; else echo "$FAKE_ZEN" > "$FAKE_ADB_LOG.zen"; echo "$FAKE_ZEN"; fi ;;
            "shell run-as org.hapticon.app cat shared_prefs/chat.xml") printf '%%s' "%s" ;;
            "shell run-as org.hapticon.app cat shared_prefs/chat_credentials.xml") echo "run-as: no such file" ;;
            install*) printf 'Performing Streamed Install\\nSuccess\\n' ;;
            "shell am instrument"*) cat "$FAKE_INSTRUMENT" ;;
        esac
    """) % CHAT_XML

    def setUp(self):
        self.root = tempfile.mkdtemp()
        self.log = os.path.join(self.root, "adb.log")
        self.adb = os.path.join(self.root, "adb")
        with open(self.adb, "w") as f:
            f.write(self.FAKE_ADB)
        os.chmod(self.adb, 0o755)
        companion = SimpleNamespace(main_class="org.hapticon.companion.MainKt")
        self.build = SimpleNamespace(root=self.root, cache=os.path.join(self.root, ".build-cache"),
                                     tools=SimpleNamespace(java="java"), project=SimpleNamespace(module=lambda path: companion))
        self.tester = SimpleNamespace(min_sdk="31", application_id="org.hapticon.devicecheck",
                                      runner="androidx.test.runner.AndroidJUnitRunner")
        self.apks = (os.path.join(self.root, "hapticon-debug.apk"), os.path.join(self.root, "hapticon-device-check.apk"))

    def run_check(self, zen="0", zen_after="0", rest=()):
        out = io.StringIO()
        broker = mock.MagicMock(users={"phone-ab12": "pw1", "peer-ab12": "pw2"}, port=41883)
        env = {"FAKE_ADB_LOG": self.log, "FAKE_INSTRUMENT": os.path.join(FIXTURES, "am-instrument-r.txt"), "FAKE_ZEN": zen, "FAKE_ZEN_AFTER": zen_after}
        with mock.patch.dict(os.environ, env), mock.patch.object(device_check, "Broker", return_value=broker), \
                mock.patch("hapticon_build.__main__.companion_classpath", return_value=["companion.jar"]), \
                mock.patch.object(device_check, "adb_server_running", return_value=True):
            os.environ.pop("ANDROID_SERIAL", None)
            code = device_check.run(self.build, list(rest), *self.apks, self.tester, out, find=lambda cache: (self.adb, ""))
        return code, out.getvalue(), open(self.log).read().splitlines(), broker

    def test_recordedRun_installsBrokerReverseInstrumentRestore_reportsEachTest_exit1OnAFailure(self):
        code, output, calls, broker = self.run_check()
        self.assertEqual(1, code)
        self.assertEqual([
            "devices",
            "-s R58M123 shell getprop ro.build.version.sdk",
            "-s R58M123 shell getprop ro.product.model",
            "-s R58M123 shell getprop ro.build.version.release",
            "-s R58M123 shell settings get global zen_mode",
            f"-s R58M123 install -r -t -g {self.apks[0]}",
            f"-s R58M123 install -r -t -g {self.apks[1]}",
            "-s R58M123 shell run-as org.hapticon.app cat shared_prefs/chat.xml",
            "-s R58M123 shell run-as org.hapticon.app cat shared_prefs/chat_credentials.xml",
            "-s R58M123 reverse tcp:1883 tcp:41883",
            "-s R58M123 shell am instrument -w -r -e broker tcp://127.0.0.1:1883 -e user phone-ab12 -e password pw1 "
            "-e peer peer-ab12 -e peerPassword pw2 org.hapticon.devicecheck/androidx.test.runner.AndroidJUnitRunner",
            "-s R58M123 reverse --remove tcp:1883",
            "-s R58M123 shell settings get global zen_mode",
            "-s R58M123 shell am force-stop org.hapticon.app",
            # the phone's own account back as it was: the settings it had, none where it had none
            f"-s R58M123 shell run-as org.hapticon.app sh -c 'cat > shared_prefs/chat.xml' <<{len(self.CHAT_XML)}",
            "-s R58M123 shell run-as org.hapticon.app rm -f shared_prefs/chat_credentials.xml",
        ], calls)
        broker.start.assert_called_once()
        broker.stop.assert_called_once()
        lines = output.splitlines()
        self.assertEqual("device-check: Pixel 7 (R58M123, Android 15, API 35); installing, then 3 tests of about a minute each",
                         lines[0])
        self.assertTrue(lines[1].startswith("PASS ReceivedKnockTest#swipedAwayScreenOff_"))
        self.assertIn("     note: knock: COMMUNICATION_REQUEST, finished, 560 ms", output)
        self.assertIn("FAIL ReceivedKnockTest#conversationOpenScreenOff_knockStillFeltAndNotified_noRead", output)
        self.assertIn("SKIP ReceivedKnockTest#doNotDisturb_knockArrivesButNothingVibrates_noFelt", output)
        self.assertEqual("device-check: 1 passed, 1 failed, 1 skipped on Pixel 7 (Android 15, API 35)", lines[-1])

    def test_oneTest_passedToTheRunnerAsItsClassArgument(self):
        _, _, calls, _ = self.run_check(rest=["--tests", "ReceivedKnockTest#doNotDisturb_knockArrivesButNothingVibrates_noFelt"])
        instrument = next(c for c in calls if " am instrument " in c)
        self.assertIn("-e class org.hapticon.devicecheck.ReceivedKnockTest#doNotDisturb_knockArrivesButNothingVibrates_noFelt "
                      "org.hapticon.devicecheck/", instrument)

    def test_suiteEndsWithDoNotDisturbOn_thePhonesOwnModeRestored(self):
        for before, after, restore in (("0", "2", "off"), ("1", "0", "priority"), ("3", "2", "alarms")):
            self.setUp()  # a fresh phone
            _, _, calls, _ = self.run_check(zen=before, zen_after=after)
            self.assertIn(f"-s R58M123 shell cmd notification set_dnd {restore}", calls)

    def test_modeAsItWas_notTouched(self):
        _, _, calls, _ = self.run_check(zen="1", zen_after="1")
        self.assertFalse(any("set_dnd" in c for c in calls))


class FindAdbTest(unittest.TestCase):
    def setUp(self):
        self.home = tempfile.mkdtemp()
        self.cache = tempfile.mkdtemp()
        self.fetched = []

    def executable(self, *parts):
        path = os.path.join(*parts)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write("#!/bin/sh\n")
        os.chmod(path, 0o755)
        return path

    def find(self, env):
        return device_check.find_adb(self.cache, env, self.home, fetch=lambda cache: self.fetched.append(cache) or (None, "no"))

    def test_onPath_first(self):
        on_path = self.executable(tempfile.mkdtemp(), "adb")
        sdk = tempfile.mkdtemp()
        self.executable(sdk, "platform-tools", "adb")
        self.assertEqual((on_path, ""), self.find({"PATH": os.path.dirname(on_path), "ANDROID_HOME": sdk}))

    def test_androidHomePlatformTools_thenStudiosDefaultSdk(self):
        sdk = tempfile.mkdtemp()
        in_sdk = self.executable(sdk, "platform-tools", "adb")
        self.assertEqual((in_sdk, ""), self.find({"PATH": "", "ANDROID_HOME": sdk}))
        studio = self.executable(self.home, "Android", "Sdk", "platform-tools", "adb")
        self.assertEqual((studio, ""), self.find({"PATH": ""}))
        self.assertEqual([], self.fetched)

    def test_noneInstalled_fetchesOne(self):
        self.assertEqual((None, "no"), self.find({"PATH": ""}))
        self.assertEqual([self.cache], self.fetched)

    def test_adbVariableNotExecutable_saysSo(self):
        self.assertEqual((None, "$ADB=/nowhere/adb is not executable"), self.find({"ADB": "/nowhere/adb", "PATH": ""}))

    def test_fetchAdb_wheelInTheCache_unpacksItsAdbExecutable(self):
        import zipfile
        wheels = os.path.join(self.cache, "wheels")
        os.makedirs(wheels)
        with zipfile.ZipFile(os.path.join(wheels, f"adbutils-{device_check.ADBUTILS_VERSION}-py3-none-manylinux1_x86_64.whl"), "w") as z:
            z.writestr("adbutils/binaries/adb", b"\x7fELF adb")
        path, why = device_check.fetch_adb(self.cache)
        self.assertEqual("", why)
        self.assertEqual(b"\x7fELF adb", open(path, "rb").read())
        self.assertTrue(os.access(path, os.X_OK))

    def test_fetchAdb_wheelWithoutAdb_saysSo(self):
        import zipfile
        wheels = os.path.join(self.cache, "wheels")
        os.makedirs(wheels)
        with zipfile.ZipFile(os.path.join(wheels, f"adbutils-{device_check.ADBUTILS_VERSION}-py3-none-any.whl"), "w") as z:
            z.writestr("adbutils/__init__.py", "")
        path, why = device_check.fetch_adb(self.cache)
        self.assertIsNone(path)
        self.assertIn("has no adb for this platform", why)


if __name__ == "__main__":
    unittest.main()
