"""The project model: modules, plugins and dependencies read from the Gradle files.

Only a declarative subset of the Kotlin DSL is understood (see docs/build.md). Anything inside
`plugins {}` or `dependencies {}` that is not understood is an error, so a dependency can never be
silently ignored by the offline build while Gradle would use it.
"""
from __future__ import annotations

import os
import re
import tomllib
from dataclasses import dataclass, field

from .errors import BuildError


@dataclass(frozen=True)
class Coordinate:
    group: str
    name: str
    version: str | None  # None: the version comes from a platform (BOM)

    def __str__(self) -> str:
        return f"{self.group}:{self.name}" + (f":{self.version}" if self.version else "")


@dataclass
class Dependency:
    configuration: str           # implementation, api, testImplementation, debugImplementation, ksp, ...
    project: str | None = None   # ":haptics-core"
    library: Coordinate | None = None
    platform: bool = False
    # Gradle's `{ exclude(group = "g", module = "m") }`: (group, module or "*") left out of this dependency's graph
    excludes: frozenset = frozenset()


@dataclass
class Module:
    path: str                    # ":app"
    directory: str
    plugins: set[str] = field(default_factory=set)     # catalog plugin aliases or core plugin ids
    plugin_ids: set[str] = field(default_factory=set)  # the Gradle plugin ids behind them
    dependencies: list[Dependency] = field(default_factory=list)
    explicit_api: bool = False
    main_class: str | None = None
    ksp_args: dict[str, str] = field(default_factory=dict)
    android: dict[str, str] = field(default_factory=dict)
    # The convention plugins' scripts this module applies (directly or through another convention), in order.
    conventions: list[str] = field(default_factory=list)

    @property
    def name(self) -> str:
        return self.path.lstrip(":").replace(":", "-")

    @property
    def is_android_app(self) -> bool:
        return "android-application" in self.plugins

    @property
    def is_android_library(self) -> bool:
        return "android-library" in self.plugins

    @property
    def is_android_test(self) -> bool:
        """A `com.android.test` module: an instrumentation APK of its own that tests another module's app."""
        return "android-test" in self.plugins

    @property
    def is_android(self) -> bool:
        return self.is_android_app or self.is_android_library or self.is_android_test

    @property
    def compiler_plugins(self) -> list[str]:
        """Catalog aliases of the Kotlin compiler plugins the applied Gradle plugins add (see COMPILER_PLUGINS)."""
        return [tool for plugin_id, tool in COMPILER_PLUGINS.items() if plugin_id in self.plugin_ids]

    @property
    def uses_ksp(self) -> bool:
        return "ksp" in self.plugins

    def deps(self, *configurations: str) -> list[Dependency]:
        return [d for d in self.dependencies if d.configuration in configurations]


class Catalog:
    """gradle/libs.versions.toml, with Gradle's accessor naming (`libs.a.b.c` is alias a-b-c, a_b_c or a.b.c)."""

    def __init__(self, path: str):
        try:
            with open(path, "rb") as f:
                data = tomllib.load(f)
        except FileNotFoundError:
            raise BuildError(f"version catalog not found: {path}")
        self.versions: dict[str, str] = {k: str(v) for k, v in data.get("versions", {}).items()}
        self._libraries = {self._key(k): (k, v) for k, v in data.get("libraries", {}).items()}
        self._plugins = {self._key(k): (k, v) for k, v in data.get("plugins", {}).items()}
        self._versions_by_key = {self._key(k): v for k, v in self.versions.items()}

    @staticmethod
    def _key(alias: str) -> str:
        return re.sub(r"[-_.]", ".", alias).lower()

    def version(self, accessor: str) -> str:
        try:
            return self._versions_by_key[self._key(accessor)]
        except KeyError:
            raise BuildError(f"libs.versions.{accessor} is not declared in gradle/libs.versions.toml")

    def library(self, accessor: str) -> Coordinate:
        entry = self._libraries.get(self._key(accessor))
        if entry is None:
            raise BuildError(f"libs.{accessor} is not declared in [libraries] of gradle/libs.versions.toml")
        alias, spec = entry
        if isinstance(spec, str):
            g, a, v = spec.split(":")
            return Coordinate(g, a, v)
        if "module" in spec:
            g, a = spec["module"].split(":")
        else:
            g, a = spec["group"], spec["name"]
        v = spec.get("version")
        if isinstance(v, dict):
            if "ref" not in v:
                raise BuildError(f"library {alias}: only version.ref or a plain version is supported")
            v = self.versions.get(v["ref"])
            if v is None:
                raise BuildError(f"library {alias}: version.ref {spec['version']['ref']!r} is not in [versions]")
        elif "version.ref" in spec:  # dotted key form
            v = self.versions[spec["version.ref"]]
        return Coordinate(g, a, v)

    def plugin_alias(self, accessor: str) -> str:
        return self._plugin(accessor)[0]

    def plugin_id(self, accessor: str) -> str:
        """The Gradle plugin id (`id = "…"`) behind `libs.plugins.<accessor>`."""
        alias, spec = self._plugin(accessor)
        if isinstance(spec, str):  # "id:version" shorthand
            return spec.split(":")[0]
        if "id" not in spec:
            raise BuildError(f"plugin {alias} has no id in gradle/libs.versions.toml")
        return spec["id"]

    def plugin_alias_of_id(self, plugin_id: str) -> str | None:
        """The [plugins] alias whose id is [plugin_id], or None."""
        for alias, spec in self._plugins.values():
            if (spec.split(":")[0] if isinstance(spec, str) else spec.get("id")) == plugin_id:
                return alias
        return None

    def plugin_has_version(self, accessor: str) -> bool:
        spec = self._plugin(accessor)[1]
        return isinstance(spec, str) and ":" in spec or isinstance(spec, dict) and any(k.startswith("version") for k in spec)

    def _plugin(self, accessor: str) -> tuple:
        entry = self._plugins.get(self._key(accessor))
        if entry is None:
            raise BuildError(f"libs.plugins.{accessor} is not declared in [plugins] of gradle/libs.versions.toml")
        return entry

    def tool(self, alias: str) -> Coordinate:
        return self.library(alias)

    def tool_aliases(self, prefix: str) -> list[str]:
        """Every [libraries] alias that starts with `prefix` (as written in the catalog), in catalog order."""
        return [alias for alias, _spec in self._libraries.values() if alias.startswith(prefix)]


CONFIGURATIONS = {
    "implementation", "api", "compileOnly", "runtimeOnly",
    "testImplementation", "testRuntimeOnly", "testCompileOnly",
    "debugImplementation", "ksp",
}
CORE_PLUGINS = {"application", "java-library", "java"}

COMPOSE_PLUGIN = "org.jetbrains.kotlin.plugin.compose"
SERIALIZATION_PLUGIN = "org.jetbrains.kotlin.plugin.serialization"
# Gradle plugins that only add a Kotlin compiler plugin (as the Kotlin Gradle plugin does), by plugin id → the
# catalog alias of the compiler plugin jar, which must be at the Kotlin version (the compiler's plugin API).
COMPILER_PLUGINS = {
    COMPOSE_PLUGIN: "tool-compose-compiler-plugin",
    SERIALIZATION_PLUGIN: "tool-serialization-compiler-plugin",
}


def _read(path: str) -> str:
    with open(path, encoding="utf-8") as f:
        return f.read()


def _block(text: str, name: str) -> str | None:
    """Body of the first top-level `name { ... }` block (brace matched), or None."""
    m = re.search(r"(?m)^\s*" + re.escape(name) + r"\s*\{", text)
    if not m:
        return None
    depth, i = 1, m.end()
    while depth and i < len(text):
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
    if depth:
        raise BuildError(f"unbalanced braces in block {name}")
    return text[m.end(): i - 1]


def _statements(body: str) -> list[str]:
    lines = []
    for raw in body.splitlines():
        line = re.sub(r"//.*$", "", raw).strip()
        if line:
            lines.append(line)
    return lines


def _value(expr: str, catalog: Catalog) -> str:
    expr = expr.strip()
    m = re.fullmatch(r'"([^"]*)"', expr)
    if m:
        return m.group(1)
    m = re.fullmatch(r"libs\.versions\.([\w.]+)\.get\(\)(?:\.toInt\(\))?", expr)
    if m:
        return catalog.version(m.group(1))
    if re.fullmatch(r"\d+", expr):
        return expr
    raise BuildError(f"cannot evaluate {expr!r}: use a literal or libs.versions.x.get()")


def _excludes(block: str, build_file: str) -> frozenset:
    """`exclude(group = "g")` / `exclude(group = "g", module = "m")` statements (one line, `;`-separated)."""
    found = set()
    for stmt in filter(None, (s.strip() for s in block.split(";"))):
        m = re.fullmatch(r'exclude\(group\s*=\s*"([^"]+)"(?:\s*,\s*module\s*=\s*"([^"]+)")?\)', stmt)
        if not m:
            raise BuildError(f"{build_file}: dependencies: cannot read {stmt!r} (only exclude(group = …, module = …))")
        found.add((m.group(1), m.group(2) or "*"))
    return frozenset(found)


def conventions_of(root: str, settings_text: str) -> dict[str, str]:
    """
    The convention plugins of the builds that settings.gradle.kts includes in `pluginManagement {}`
    (`includeBuild("build-logic")`): plugin id → script. Gradle makes every `src/main/kotlin/<id>.gradle.kts` of
    such a build a precompiled script plugin with that id (docs/build.md "Conventions").
    """
    found = {}
    for build in re.findall(r'includeBuild\("([^"]+)"\)', _block(settings_text, "pluginManagement") or ""):
        sources = os.path.join(root, build, "src", "main", "kotlin")
        if not os.path.isdir(sources):
            raise BuildError(f"settings.gradle.kts includes the plugin build {build}, which has no src/main/kotlin")
        for name in sorted(os.listdir(sources)):
            if name.endswith(".gradle.kts"):
                found[name[: -len(".gradle.kts")]] = os.path.join(sources, name)
    return found


def parse_module(path: str, directory: str, catalog: Catalog, conventions: dict[str, str] | None = None) -> Module:
    build_file = os.path.join(directory, "build.gradle.kts")
    try:
        text = _read(build_file)
    except FileNotFoundError:
        raise BuildError(f"module {path} is included in settings.gradle.kts but {build_file} does not exist")
    module = Module(path=path, directory=directory)
    _apply_script(module, build_file, text, catalog, conventions or {}, convention=False)

    application = _block(text, "application")
    if application:
        m = re.search(r'mainClass(?:\.set\(|\s*=\s*)"([\w.$]+)"', application)
        if not m:
            raise BuildError(f"{build_file}: application {{}} needs mainClass = \"...\"")
        module.main_class = m.group(1)

    android = _block(text, "android")
    if android is not None:
        for key in ("namespace", "compileSdk", "minSdk", "targetSdk", "applicationId", "versionCode", "versionName",
                    "testInstrumentationRunner", "targetProjectPath"):
            m = re.search(r"(?:^|[\s{;])" + key + r"\s*=\s*([^\n;}]+?)\s*(?=$|[;}\n])", android, re.M)
            if m:
                module.android[key] = _value(m.group(1), catalog)
        # AGP's experimental flag of a test module whose instrumentation targets its own package (macrobenchmark's
        # setting): the tests run in a process and uid of their own, beside the app they drive.
        for name, value in re.findall(r'experimentalProperties\["([\w.-]+)"\]\s*=\s*(true|false)', android):
            module.android[name] = value
        # A library states the targetSdk its unit tests run with in testOptions { targetSdk = … }.
        for key in ("namespace", "compileSdk", "minSdk", "targetSdk"):
            if key not in module.android:
                raise BuildError(f"{build_file}: android {{}} must set {key}")
        if module.is_android_test:
            for key in ("targetProjectPath", "testInstrumentationRunner"):
                if key not in module.android:
                    raise BuildError(f"{build_file}: a test module's android {{}} must set {key}")
    if module.is_android and android is None:
        raise BuildError(f"{build_file}: an Android module needs an android {{}} block")
    return module


def _apply_script(module: Module, build_file: str, text: str, catalog: Catalog, conventions: dict[str, str],
                  convention: bool) -> None:
    """
    Adds what a build script declares in plugins {}, dependencies {}, kotlin {} and ksp {} to [module]. A plugin that
    is one of the project's [conventions] is applied as Gradle applies a precompiled script plugin: its script's
    declarations come first, at the point of the plugins {} block, then the applying script's own.
    """
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    if convention:
        for name in ("android", "application", "ksp"):
            if _block(text, name) is not None:
                raise BuildError(f"{build_file}: a convention plugin may declare plugins {{}}, kotlin {{}} and "
                                 f"dependencies {{}} only, not {name} {{}} (keep it in the module's build file)")

    for stmt in _statements(_block(text, "plugins") or ""):
        m = re.fullmatch(r"alias\(libs\.plugins\.([\w.]+)\)", stmt)
        im = re.fullmatch(r'id\("([\w.-]+)"\)', stmt)
        if m:
            plugin_id, alias = catalog.plugin_id(m.group(1)), catalog.plugin_alias(m.group(1))
            if plugin_id not in conventions and not catalog.plugin_has_version(m.group(1)):
                raise BuildError(f"{build_file}: plugins: {stmt} has no version in gradle/libs.versions.toml and no "
                                 f"convention script {plugin_id}.gradle.kts in a build that settings.gradle.kts includes")
        elif im:
            plugin_id, alias = im.group(1), catalog.plugin_alias_of_id(im.group(1))
            if plugin_id not in conventions and alias is None:
                raise BuildError(f"{build_file}: plugins: {stmt} is neither a [plugins] id of gradle/libs.versions.toml "
                                 f"nor a convention plugin")
        elif stmt in CORE_PLUGINS or re.fullmatch(r"`[\w-]+`", stmt):
            plugin_id = alias = stmt.strip("`")
        else:
            raise BuildError(f"{build_file}: plugins: cannot read {stmt!r} (use alias(libs.plugins.x))")
        if plugin_id in conventions:
            script = conventions[plugin_id]
            if script in module.conventions:
                continue  # Gradle applies a plugin once
            module.conventions.append(script)
            _apply_script(module, script, _read(script), catalog, conventions, convention=True)
            continue
        module.plugins.add(alias)
        module.plugin_ids.add(plugin_id)

    for stmt in _statements(_block(text, "dependencies") or ""):
        m = re.fullmatch(r"(\w+)\((.*?\)?)\)\s*(?:\{(.*)\})?", stmt)
        if not m or m.group(1) not in CONFIGURATIONS:
            raise BuildError(f"{build_file}: dependencies: cannot read {stmt!r}")
        conf, arg = m.group(1), m.group(2).strip()
        excludes = _excludes(m.group(3), build_file) if m.group(3) is not None else frozenset()
        pm = re.fullmatch(r'project\("(:[\w:-]+)"\)', arg)
        lm = re.fullmatch(r"libs\.([\w.]+)", arg)
        # A convention reaches the catalog by name (precompiled script plugins get no `libs` accessor).
        fm = re.fullmatch(r'libs\.findLibrary\("([\w.-]+)"\)\.get\(\)', arg)
        plm = re.fullmatch(r"platform\(libs\.([\w.]+)\)", arg)
        if pm and convention:
            raise BuildError(f"{build_file}: dependencies: a convention plugin declares libraries only; "
                             f"declare {arg} in the module's build file (the architecture check reads it there)")
        if pm:
            module.dependencies.append(Dependency(conf, project=pm.group(1)))
        elif lm or fm:
            accessor = (lm or fm).group(1)
            module.dependencies.append(Dependency(conf, library=catalog.library(accessor), excludes=excludes))
        elif plm:
            module.dependencies.append(Dependency(conf, library=catalog.library(plm.group(1)), platform=True))
        else:
            raise BuildError(f"{build_file}: dependencies: {arg!r} must be project(\":x\"), libs.x or platform(libs.x)")

    kotlin = _block(text, "kotlin") or ""
    module.explicit_api = module.explicit_api or "explicitApi()" in kotlin

    for key, value in re.findall(r'arg\("([^"]+)",\s*"([^"]*)"\)', _block(text, "ksp") or ""):
        module.ksp_args[key] = value.replace("$projectDir", module.directory).replace("${projectDir}", module.directory)


@dataclass
class Project:
    root: str
    name: str
    catalog: Catalog
    modules: dict[str, Module]

    def module(self, path: str) -> Module:
        if not path.startswith(":"):
            path = ":" + path
        if path not in self.modules:
            raise BuildError(f"no module {path}; modules: {', '.join(self.modules)}")
        return self.modules[path]

    def project_deps(self, module: Module, *configurations: str) -> list[Module]:
        return [self.module(d.project) for d in module.deps(*configurations) if d.project]

    def in_dependency_order(self) -> list[Module]:
        order, state = [], {}

        def visit(m: Module, chain: tuple[str, ...]):
            if state.get(m.path) == "done":
                return
            if state.get(m.path) == "visiting":
                raise BuildError("module dependency cycle: " + " -> ".join(chain + (m.path,)))
            state[m.path] = "visiting"
            for d in m.dependencies:  # test-only project dependencies may point back; they don't order modules
                if d.project and not d.configuration.startswith("test"):
                    visit(self.module(d.project), chain + (m.path,))
            state[m.path] = "done"
            order.append(m)

        for m in self.modules.values():
            visit(m, ())
        return order


def load_project(root: str) -> Project:
    settings = os.path.join(root, "settings.gradle.kts")
    try:
        text = _read(settings)
    except FileNotFoundError:
        raise BuildError(f"{settings} not found: run ./build from the project root")
    name_match = re.search(r'rootProject\.name\s*=\s*"([^"]+)"', text)
    catalog = Catalog(os.path.join(root, "gradle", "libs.versions.toml"))
    conventions = conventions_of(root, text)
    modules = {}
    for path in re.findall(r'(?m)^\s*include\("(:[\w:-]+)"\)', text):
        directory = os.path.join(root, *path.strip(":").split(":"))
        modules[path] = parse_module(path, directory, catalog, conventions)
    if not modules:
        raise BuildError(f"{settings} includes no modules")
    return Project(root, name_match.group(1) if name_match else "project", catalog, modules)
