"""The instrumentation APK of a `com.android.test` module, built as AGP builds one (docs/build.md, "Test modules").

AGP gives a test module's manifest an `<instrumentation>` element naming `testInstrumentationRunner` and the package it
instruments: the tested app's (`targetProjectPath`), or the test APK's own when the module sets
`experimentalProperties["android.experimental.self-instrumenting"] = true` (macrobenchmark's setting). Only the
self-instrumenting kind is built here: its tests run in a process and uid of their own, so the APK carries every class
it needs, and nothing is shared with the app's APK.
"""
from __future__ import annotations

import hashlib
import os
import re
import zipfile

from .android import AndroidApp, _add_tree, _dex_order, dex_type_names
from .errors import BuildError
from .toolchain import run
from .ui import Stage, info

SELF_INSTRUMENTING = "android.experimental.self-instrumenting"
EMPTY_MANIFEST = '<manifest xmlns:android="http://schemas.android.com/apk/res/android">\n</manifest>\n'


def with_instrumentation(manifest: str, runner: str, target_package: str, label: str) -> str:
    """[manifest] with the `<instrumentation>` element AGP generates for a test APK added as its last child."""
    element = (f'    <instrumentation android:name="{runner}" android:targetPackage="{target_package}"\n'
               f'        android:handleProfiling="false" android:functionalTest="false" android:label="{label}" />\n')
    if re.search(r"<instrumentation\b", re.sub(r"<!--.*?-->", "", manifest, flags=re.S)):
        raise BuildError("a test module's manifest must not declare <instrumentation>: the build writes it from "
                         "testInstrumentationRunner and targetProjectPath")
    closed = re.search(r"<manifest\b[^>]*/>", manifest)
    if closed:
        opening = closed.group(0)[:-2].rstrip() + ">\n"
        return manifest[:closed.start()] + opening + element + "</manifest>" + manifest[closed.end():]
    end = manifest.rfind("</manifest>")
    if end < 0:
        raise BuildError("the test module's manifest has no </manifest>")
    return manifest[:end] + element + manifest[end:]


def instrumentation_of(xmltree: str) -> dict[str, str] | None:
    """The attributes of the `<instrumentation>` element in `aapt2 dump xmltree --file AndroidManifest.xml` output
    (`A: http://schemas.android.com/apk/res/android:name(0x01010003)="…" (Raw: "…")` lines under `E: instrumentation`),
    by local name; None without one."""
    lines = xmltree.splitlines()
    for i, line in enumerate(lines):
        m = re.match(r"(\s*)E: instrumentation\b", line)
        if not m:
            continue
        depth, found = len(m.group(1)), {}
        for attr in lines[i + 1:]:
            a = re.match(r"(\s*)A: (?:[^:]*:)*?([\w]+)(?:\(0x[0-9a-f]+\))?=\"?([^\"(]*)", attr)
            if not a or len(a.group(1)) <= depth:
                break
            found[a.group(2)] = a.group(3).strip()
        return found
    return None


class InstrumentationApk(AndroidApp):
    """A `com.android.test` module's APK: its classes and every library they use, dexed without shrinking (test runners
    find tests and rules by reflection), its manifest with the instrumentation element, signed with the debug key."""

    def __init__(self, build, module):
        super().__init__(build, module)
        self.target = build.project.module(module.android["targetProjectPath"])
        self.target_package = self.target.android.get("applicationId", self.target.android["namespace"])
        self.runner = module.android["testInstrumentationRunner"]
        if module.android.get(SELF_INSTRUMENTING) != "true":
            raise BuildError(f"{module.path}: only a self-instrumenting test module can be built here (set "
                             f'experimentalProperties["{SELF_INSTRUMENTING}"] = true); one that runs inside '
                             f"{self.target_package} would need the app's classes left out of its APK")
        self.instrumented_package = self.application_id
        self.apk = os.path.join(self.out, f"{build.project.name}-{module.name}.apk")

    def _main_manifest(self) -> str:
        main = os.path.join(self.src, "AndroidManifest.xml")
        text = open(main).read() if os.path.exists(main) else EMPTY_MANIFEST
        if "<uses-sdk" in text:
            raise BuildError(f"{main}: declare minSdk/targetSdk in build.gradle.kts, not <uses-sdk>")
        return with_instrumentation(text, self.runner, self.instrumented_package, f"Tests for {self.target_package}")

    def _dex(self, project_entries: list[str], library_jars: list[str]) -> list[str]:
        """The libraries dexed whole by D8, once per exact set (`.build-cache/test-library-dex/`), then the module's own
        classes (and R classes) against them; no class may come from both."""
        key = hashlib.sha1(f"{self.min_sdk}:{self.tools.r8}".encode())
        for j in library_jars:
            key.update(j.encode() + str(os.path.getsize(j)).encode())
        cache = os.path.join(self.b.cache, "test-library-dex", key.hexdigest()[:16])
        if not os.path.exists(os.path.join(cache, ".done")):
            os.makedirs(os.path.join(cache, "dex"), exist_ok=True)
            with Stage(f"D8 of {len(library_jars)} library jars (cached until they change)"):
                self._d8(["--output", os.path.join(cache, "dex"), *library_jars], "D8 of the test APK's libraries")
            open(os.path.join(cache, ".done"), "w").close()
        library_dex = sorted((os.path.join(cache, "dex", f) for f in os.listdir(os.path.join(cache, "dex"))
                              if f.endswith(".dex")), key=_dex_order)
        work = os.path.join(self.out, "intermediates", "dex")
        program = os.path.join(work, "program.jar")
        os.makedirs(work, exist_ok=True)
        with zipfile.ZipFile(program, "w") as z:
            for entry in project_entries + [self.r_jar]:
                _add_tree(z, entry, classes_only=True)
        program_dex = self._dex_program(program, library_jars, library_dex, os.path.join(work, "program"))
        return library_dex + program_dex

    def verify(self, apk: str, debuggable: bool = True) -> None:
        """Signature (apksig), package and SDK levels (aapt2 badging), the instrumentation element (aapt2 xmltree) and
        that the dex defines its runner."""
        helper = self.tools.helper_classes("ApkTool", [self.tools.apksig])
        sig = run([self.tools.java, "-cp", os.pathsep.join([helper, self.tools.apksig]), "ApkTool", "verify", apk,
                   self.min_sdk], "APK signature verification").strip()
        badging = run([self.tools.aapt2, "dump", "badging", apk], "aapt2 dump badging")
        package = re.search(r"package: name='([^']+)'", badging)
        if not package or package.group(1) != self.application_id:
            raise BuildError(f"test APK package is {package and package.group(1)}, expected {self.application_id}")
        sdk = re.search(r"(?m)^(?:minSdkVersion|sdkVersion):'(\d+)'", badging)
        if not sdk or sdk.group(1) != self.min_sdk:
            raise BuildError(f"test APK minSdk is {sdk and sdk.group(1)}, expected {self.min_sdk}")
        xmltree = run([self.tools.aapt2, "dump", "xmltree", "--file", "AndroidManifest.xml", apk], "aapt2 dump xmltree")
        element = instrumentation_of(xmltree) or {}
        if element.get("name") != self.runner or element.get("targetPackage") != self.instrumented_package:
            raise BuildError(f"test APK instrumentation is {element or 'missing'}, expected {self.runner} "
                             f"instrumenting {self.instrumented_package}")
        descriptor = "L" + self.runner.replace(".", "/") + ";"
        with zipfile.ZipFile(apk) as z:
            dexes = [n for n in z.namelist() if re.fullmatch(r"classes\d*\.dex", n)]
            if not any(descriptor in dex_type_names(z.read(n)) for n in dexes):
                raise BuildError(f"no dex in the test APK defines the runner {descriptor}")
        info(f"{sig}; package {self.application_id}, instrumentation {self.runner} of {self.instrumented_package}, "
             f"minSdk {self.min_sdk}, {len(dexes)} dex, {os.path.getsize(apk) / 1e6:.2f} MB")


def apk_builder(build, module) -> AndroidApp:
    """The builder of [module]'s APK: an app's, or a test module's instrumentation APK."""
    return InstrumentationApk(build, module) if module.is_android_test else AndroidApp(build, module)
