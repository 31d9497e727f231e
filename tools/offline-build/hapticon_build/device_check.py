"""`./build device-check`: the device check's instrumented suite on a phone over adb (docs/device-check.md).

Builds the debug app and the device-check test APK; with a phone attached, starts the embedded broker on this machine
with two throwaway users, lets the phone reach it at 127.0.0.1:1883 (`adb reverse`), installs both APKs, runs
`am instrument -w -r` and prints each test's result, its notes and a summary. Without adb or a phone it says so in one
line and exits 0: the APKs are built, which is all this machine can check.
"""
from __future__ import annotations

import os
import re
import secrets
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time
import zipfile
from dataclasses import dataclass, field

from .errors import BuildError

PHONE_PORT = 1883  # where the app looks on the phone: tcp://127.0.0.1:1883, forwarded to the broker here
RUNNER = "androidx.test.runner.AndroidJUnitRunner"
APP_PACKAGE = "org.hapticon.app"
# Zen modes (Settings.Global.ZEN_MODE) and the `cmd notification set_dnd` word that restores each.
ZEN_MODES = {"0": "off", "1": "priority", "2": "on", "3": "alarms"}
# AndroidJUnitRunner's status codes (InstrumentationResultPrinter); 2 is the device check's own note (ReceivedKnockTest).
START, OK, ERROR, FAILURE, IGNORED, ASSUMPTION_FAILURE, NOTE = 1, 0, -1, -2, -3, -4, 2


# Google's adb (platform-tools 36.0.0) as PyPI's adbutils ships it inside its platform wheels (adbutils/binaries/adb):
# where neither PATH nor an Android SDK has one, the build fetches it as it fetches a Java runtime (toolchain.py).
ADBUTILS_VERSION = "2.12.0"


def skipped_line(reason: str) -> str:
    """The one line `./build device-check` prints when it cannot run the suite (exit 0: the APKs are built)."""
    return f"device-check: {reason}; skipped"


def find_adb(cache: str, env=os.environ, home: str = os.path.expanduser("~"), fetch=None) -> tuple[str | None, str]:
    """adb: `$ADB`, else on PATH, else in an Android SDK's platform-tools (`$ANDROID_HOME`, `$ANDROID_SDK_ROOT`,
    Android Studio's default SDK folders), else the copy in PyPI's adbutils wheel ([fetch_adb]). Returns its path, or
    None and why none was found."""
    if env.get("ADB"):
        return (env["ADB"], "") if os.access(env["ADB"], os.X_OK) else (None, f"$ADB={env['ADB']} is not executable")
    on_path = shutil.which("adb", path=env.get("PATH", ""))
    if on_path:
        return on_path, ""
    sdks = [env.get("ANDROID_HOME"), env.get("ANDROID_SDK_ROOT"), os.path.join(home, "Android", "Sdk"),
            os.path.join(home, "Library", "Android", "sdk")]
    for sdk in filter(None, sdks):
        candidate = os.path.join(sdk, "platform-tools", "adb")
        if os.access(candidate, os.X_OK):
            return candidate, ""
    return (fetch or fetch_adb)(cache)


def fetch_adb(cache: str) -> tuple[str | None, str]:
    """adb from PyPI's adbutils wheel for this platform, unpacked once into [cache]; or None and why not."""
    from .toolchain import download_wheel
    target = os.path.join(cache, "tools", f"adbutils-{ADBUTILS_VERSION}", "adb")
    if os.access(target, os.X_OK):
        return target, ""
    wheel, failure = download_wheel(cache, "adbutils", ADBUTILS_VERSION)
    why = ("adb not found: not on PATH, no Android SDK platform-tools ($ANDROID_HOME), and "
           f"`pip download adbutils=={ADBUTILS_VERSION}` ")
    if wheel is None:
        return None, why + f"failed ({failure}); install adb (Debian: apt-get install adb) or set $ADB"
    with zipfile.ZipFile(wheel) as z:
        if "adbutils/binaries/adb" not in z.namelist():
            return None, why + f"gave {os.path.basename(wheel)}, which has no adb for this platform; install adb or set $ADB"
        os.makedirs(os.path.dirname(target), exist_ok=True)
        with open(target + ".tmp", "wb") as f:
            f.write(z.read("adbutils/binaries/adb"))
    os.chmod(target + ".tmp", 0o755)
    os.replace(target + ".tmp", target)
    return target, ""


def adb_server_running(port: int = 5037) -> bool:
    """Whether an adb server already listens (adb's default port): one this run starts, it stops again."""
    with socket.socket() as s:
        s.settimeout(1)
        return s.connect_ex(("127.0.0.1", port)) == 0


def attached(adb_devices: str) -> tuple[list[str], list[str]]:
    """Serials `adb devices` lists as ready ("device"), and the others with their state ("unauthorized", "offline")."""
    ready, other = [], []
    lines = adb_devices.splitlines()
    listed = next((i for i, line in enumerate(lines) if line.startswith("List of devices attached")), len(lines))
    for line in lines[listed + 1:]:
        parts = line.split()
        if len(parts) >= 2 and not line.startswith("*"):  # "* daemon started successfully" and the like
            (ready if parts[1] == "device" else other).append(parts[0] if parts[1] == "device" else f"{parts[0]} {parts[1]}")
    return ready, other


@dataclass
class TestOutcome:
    name: str                     # Class#method
    status: str = "running"       # passed, failed, skipped
    message: str = ""
    notes: list[str] = field(default_factory=list)
    seconds: float = 0.0


def parse_instrumentation(lines, on_outcome=None) -> tuple[list[TestOutcome], str]:
    """Reads `am instrument -w -r` output (raw mode: `INSTRUMENTATION_STATUS: key=value` lines, a value running on
    until the next `INSTRUMENTATION_` line, closed by `INSTRUMENTATION_STATUS_CODE: n`). Returns the tests with their
    outcomes and the run's own closing text (`INSTRUMENTATION_RESULT`/`INSTRUMENTATION_FAILED`: a crash says so there).
    [on_outcome] is called with each test as it ends."""
    outcomes: list[TestOutcome] = []
    current: dict[str, str] = {}
    key = None
    result: list[str] = []
    running: TestOutcome | None = None
    started = 0.0
    for raw in lines:
        line = raw.rstrip("\n")
        m = re.match(r"INSTRUMENTATION_STATUS: ([\w.]+)=(.*)", line)
        if m:
            key = m.group(1)
            current[key] = m.group(2)
            continue
        m = re.match(r"INSTRUMENTATION_STATUS_CODE: (-?\d+)", line)
        if m:
            code = int(m.group(1))
            name = f"{current.get('class', '?').rsplit('.', 1)[-1]}#{current.get('test', '?')}"
            if code == START:
                running, started = TestOutcome(name), time.monotonic()
                outcomes.append(running)
            elif code == NOTE and running is not None:
                running.notes.append(current.get("hapticon.note", "").strip())
            elif running is not None and code in (OK, ERROR, FAILURE, IGNORED, ASSUMPTION_FAILURE):
                running.status = {OK: "passed", IGNORED: "skipped", ASSUMPTION_FAILURE: "skipped"}.get(code, "failed")
                stack = current.get("stack", "").strip()
                running.message = stack.splitlines()[0] if stack else ""
                running.seconds = time.monotonic() - started
                if on_outcome:
                    on_outcome(running)
                running = None
            current, key = {}, None
            continue
        if line.startswith(("INSTRUMENTATION_RESULT:", "INSTRUMENTATION_FAILED:", "INSTRUMENTATION_CODE:", "INSTRUMENTATION_ABORTED:")):
            key = None
            result.append(line)
            continue
        if key is not None:
            current[key] += "\n" + line
        elif result:
            result.append(line)
    if running is not None:  # the process died mid-test
        running.status, running.message = "failed", "the test process ended before the test did (crash?)"
        if on_outcome:
            on_outcome(running)
    return outcomes, "\n".join(result).strip()


def report_line(outcome: TestOutcome) -> str:
    mark = {"passed": "PASS", "failed": "FAIL", "skipped": "SKIP"}.get(outcome.status, outcome.status.upper())
    text = f"{mark} {outcome.name} ({outcome.seconds:.1f} s)"
    if outcome.message:
        text += f"\n     {outcome.message}"
    return text + "".join(f"\n     note: {n}" for n in outcome.notes)


class Adb:
    def __init__(self, adb: str, serial: str):
        self.adb, self.serial = adb, serial

    def __call__(self, *args: str, check: bool = True, stdin: str | None = None, timeout: float = 120) -> str:
        p = subprocess.run([self.adb, "-s", self.serial, *args], input=stdin, text=True, timeout=timeout,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        if check and p.returncode != 0:
            raise BuildError(f"adb {' '.join(args)} failed (exit {p.returncode}): {p.stdout.strip()[-400:]}")
        return p.stdout

    def shell(self, command: str, **kw) -> str:
        return self("shell", command, **kw)


def free_port(preferred: int) -> int:
    for port in (preferred, 0):
        with socket.socket() as s:
            try:
                s.bind(("127.0.0.1", port))
                return s.getsockname()[1]
            except OSError:
                continue
    raise BuildError("no free TCP port on 127.0.0.1 for the broker")


class Broker:
    """The embedded broker (`hapticon broker`) on 127.0.0.1 with two throwaway users, for one run."""

    def __init__(self, java: str, classpath: list[str], main_class: str):
        self.command = [java, "-Djava.awt.headless=true", "-cp", os.pathsep.join(classpath), main_class, "broker"]
        self.data = tempfile.mkdtemp(prefix="hapticon-device-check-")
        tag = secrets.token_hex(3)
        self.users = {f"phone-{tag}": secrets.token_urlsafe(18), f"peer-{tag}": secrets.token_urlsafe(18)}
        self.process: subprocess.Popen | None = None
        self.port = 0
        self.output: list[str] = []

    def start(self) -> None:
        for user, password in self.users.items():
            secret = os.path.join(self.data, f"{user}.password")
            with open(os.open(secret, os.O_WRONLY | os.O_CREAT, 0o600), "w") as f:
                f.write(password + "\n")
            p = subprocess.run(self.command + ["adduser", user, "--data", self.data, "--password-file", secret],
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            if p.returncode != 0:
                raise BuildError(f"hapticon broker adduser {user} failed: {p.stdout.strip()[-400:]}")
        self.port = free_port(PHONE_PORT)
        self.process = subprocess.Popen(self.command + ["--data", self.data, "--port", str(self.port)],
                                        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        listening = threading.Event()
        threading.Thread(target=self._read_output, args=(listening,), daemon=True).start()
        if not listening.wait(90):
            raise BuildError(f"the embedded broker did not start within 90 s (exit {self.process.poll()}): "
                             + " / ".join(self.output[-3:]))

    def _read_output(self, listening: threading.Event) -> None:
        # Read to the end, so that the broker never blocks on a full pipe; the last lines explain a failure.
        for line in self.process.stdout:
            self.output = (self.output + [line.rstrip()])[-20:]
            if line.startswith("broker: listening"):
                listening.set()

    def stop(self) -> None:
        if self.process and self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                self.process.kill()
        shutil.rmtree(self.data, ignore_errors=True)


def main(build, rest: list[str], out=sys.stdout) -> int:
    """Builds both APKs, then runs the suite on the phone (or says why it cannot). Returns the exit code."""
    from .android import AndroidApp
    from .instrumentation import InstrumentationApk
    from .__main__ import app_module
    project = build.project
    tests_option(rest)  # a bad option fails before the build, not after it
    app_apk = AndroidApp(build, app_module(project)).assemble()
    test_module = next((m for m in project.modules.values() if m.is_android_test), None)
    if test_module is None:
        raise BuildError("no module applies the android-test plugin (device-check/build.gradle.kts)")
    tester = InstrumentationApk(build, test_module)
    test_apk = tester.assemble()
    build.kotlinc.close()
    return run(build, rest, app_apk, test_apk, tester, out)


def tests_option(rest: list[str]) -> str | None:
    """The `--tests CLASS[#METHOD]` of the command line (AndroidJUnitRunner's `-e class`), or None."""
    if not rest:
        return None
    if len(rest) != 2 or rest[0] != "--tests" or rest[1].startswith("-"):
        raise BuildError(f"device-check takes only --tests CLASS[#METHOD], got: {' '.join(rest)}")
    name = rest[1]
    return name if "." in name.split("#")[0] else "org.hapticon.devicecheck." + name


def run(build, rest: list[str], app_apk: str, test_apk: str, tester, out=sys.stdout, find=find_adb) -> int:
    """Runs the built suite on the attached phone; [tester] is the test APK's builder (its package, runner, minSdk)."""
    adb_path, why = find(build.cache)
    if adb_path is None:
        print(skipped_line(why), file=out)
        return 0
    server_was_running = adb_server_running()
    try:
        return _run_on_phone(build, rest, adb_path, app_apk, test_apk, tester, out)
    finally:
        if not server_was_running:  # leave the machine as it was: the server `adb devices` started stops
            subprocess.run([adb_path, "kill-server"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def _run_on_phone(build, rest: list[str], adb_path: str, app_apk: str, test_apk: str, tester, out) -> int:
    from .__main__ import companion_classpath
    project = build.project
    devices = subprocess.run([adb_path, "devices"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if devices.returncode != 0:
        print(skipped_line(f"`{adb_path} devices` failed: {devices.stdout.strip()[-200:]}"), file=out)
        return 0
    ready, other = attached(devices.stdout)
    if not ready:
        reason = f"adb devices lists none ready: {', '.join(other)}" if other else "adb devices lists none"
        print(skipped_line(f"no device attached ({reason})"), file=out)
        return 0
    serial = os.environ.get("ANDROID_SERIAL") or (ready[0] if len(ready) == 1 else None)
    if serial is not None and serial not in ready:
        print(skipped_line(f"ANDROID_SERIAL={serial} is not attached (adb devices lists {', '.join(ready)})"), file=out)
        return 0
    if serial is None:
        print(f"device-check: {len(ready)} devices attached ({', '.join(ready)}); choose one with ANDROID_SERIAL=SERIAL", file=out)
        return 2
    adb = Adb(adb_path, serial)
    sdk = int(adb.shell("getprop ro.build.version.sdk").strip() or 0)
    model = adb.shell("getprop ro.product.model").strip()
    release = adb.shell("getprop ro.build.version.release").strip()
    if sdk < int(tester.min_sdk):
        print(f"device-check: {model} runs Android {release} (API {sdk}); the check needs API {tester.min_sdk} "
              f"(Android 12) or later", file=out)
        return 1
    print(f"device-check: {model} ({serial}, Android {release}, API {sdk}); installing, then 3 tests of about a "
          f"minute each", file=out, flush=True)
    cp = companion_classpath(build)
    broker = Broker(build.tools.java, cp, project.module(":companion").main_class)
    saved: dict[str, str] | None = None  # the app's own account, once read: only then is it put back
    zen = adb.shell("settings get global zen_mode", check=False).strip()
    try:
        for apk in (app_apk, test_apk):
            output = adb("install", "-r", "-t", "-g", apk, check=False, timeout=300)
            if "Success" not in output:
                raise BuildError(f"installing {os.path.relpath(apk, build.root)} failed: {output.strip()[-300:]}"
                                 + (" (a Hapticon signed with another key is installed: uninstall it first)"
                                    if "UPDATE_INCOMPATIBLE" in output else ""))
        # The suite replaces the app's chat account with the throwaway one; the phone's own comes back afterwards.
        account = {}
        for name in ("chat", "chat_credentials"):
            text = adb.shell(f"run-as {APP_PACKAGE} cat shared_prefs/{name}.xml", check=False)
            if text.startswith("<?xml"):
                account[name] = text
        saved = account
        broker.start()
        adb("reverse", f"tcp:{PHONE_PORT}", f"tcp:{broker.port}")
        phone, peer = list(broker.users)
        arguments = {"broker": f"tcp://127.0.0.1:{PHONE_PORT}", "user": phone, "password": broker.users[phone],
                     "peer": peer, "peerPassword": broker.users[peer]}
        command = [adb_path, "-s", serial, "shell", "am", "instrument", "-w", "-r"]
        for k, v in arguments.items():
            command += ["-e", k, v]
        if tests_option(rest):
            command += ["-e", "class", tests_option(rest)]
        command.append(f"{tester.application_id}/{tester.runner}")
        process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        outcomes, result = parse_instrumentation(process.stdout, lambda o: print(report_line(o), file=out, flush=True))
        process.wait()
    finally:
        broker.stop()
        adb("reverse", "--remove", f"tcp:{PHONE_PORT}", check=False)
        if zen in ZEN_MODES and adb.shell("settings get global zen_mode", check=False).strip() != zen:
            adb.shell(f"cmd notification set_dnd {ZEN_MODES[zen]}", check=False)
        adb.shell(f"am force-stop {APP_PACKAGE}", check=False)
        for name in ("chat", "chat_credentials") if saved is not None else ():
            if name in saved:
                adb.shell(f"run-as {APP_PACKAGE} sh -c 'cat > shared_prefs/{name}.xml'", check=False, stdin=saved[name])
            else:  # the phone had no account: none is left behind (the throwaway one's broker is gone)
                adb.shell(f"run-as {APP_PACKAGE} rm -f shared_prefs/{name}.xml", check=False)
    passed = sum(o.status == "passed" for o in outcomes)
    failed = sum(o.status == "failed" for o in outcomes)
    skipped = sum(o.status == "skipped" for o in outcomes)
    if not outcomes or re.search(r"shortMsg=|INSTRUMENTATION_FAILED", result):
        print(f"device-check: the suite did not run to the end: {result or 'no output from am instrument'}", file=out)
        failed = failed or 1
    print(f"device-check: {passed} passed, {failed} failed, {skipped} skipped on {model} (Android {release}, API {sdk})",
          file=out)
    return 0 if failed == 0 else 1
