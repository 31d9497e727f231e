"""The dependency rules of docs/architecture.md, checked against the sources.

The rules live in docs/architecture.md, in two tables this module reads, so the document and the check
cannot drift apart:

- "Who may use whom": each module's main code may use only the modules listed for it (and itself). Both
  its build file's main-scope `project(...)` dependencies and every `import org.hapticon…` (or name
  written out in full in code) of its main sources are checked; a name is attributed to the module whose
  main sources declare its package.
- "Packages do not import each other in a cycle": inside a module, no package may import another that
  imports it back, directly or through others; each cycle is one violation naming its packages. The
  classes the Android build generates in a module's namespace (`R`, `BuildConfig`) import nothing, so a
  use of them is no edge of the package graph (they cannot close a cycle).
- "Test doubles stay in tests": no type in a module's main sources is named like a test double (a prefix
  from the section's table: `Fake…`, `InMemory…`, `Test…` …), except in the modules whose main code is test
  code and for the names the section allows, each with its reason.
- "One type per name": no two top-level types in the main sources of the modules share a simple name
  (whatever their visibility or module), except the names the section allows.
- "Features do not import each other": a package under a `feature` package (`….feature.chat`, and its
  subpackages) uses no name of a sibling feature; what two features share lives outside `feature`, and a
  screen one feature shows from another is handed in by the navigation. Nor does it use the dependency
  container (a `di` package): a route takes what it uses.

Standard library only, like the rest of the offline build: `check(root)` returns the violations as
one-line messages (empty when the project follows the rules).
"""
from __future__ import annotations

import os
import re
from dataclasses import dataclass, field

DOC = os.path.join("docs", "architecture.md")
MAIN_SOURCES = (os.path.join("src", "main", "kotlin"), os.path.join("src", "main", "java"))
PROJECT_DEP = re.compile(r'\b(\w+)\(\s*project\(\s*"(:[\w:-]+)"\s*\)')
PACKAGE = re.compile(r"^package\s+([\w.]+)", re.M)
IMPORT = re.compile(r"^import\s+([\w.]+)", re.M)
# A name written out in full in code (`org.hapticon.x.Y`) uses its module as much as an import does.
QUALIFIED = re.compile(r"(?<![\w.])([a-z]\w*(?:\.\w+)+)")
NAMESPACE = re.compile(r'^\s*namespace\s*=\s*"([\w.]+)"', re.M)
NOT_CODE = re.compile(r'//[^\n]*|/\*.*?\*/|"""(?:.|\n)*?"""|"(?:[^"\\\n]|\\.)*"|^\s*(?:package|import)\s[^\n]*', re.S | re.M)


def used_names(text: str, roots: set[str]) -> list[str]:
    """Every name the file imports, and every dotted name starting with one of [roots] (the first segment of
    the project's packages, `org`) that it writes out in full in code; comments and strings aside."""
    written = [n for n in QUALIFIED.findall(NOT_CODE.sub(" ", text)) if n.split(".", 1)[0] in roots]
    return IMPORT.findall(text) + written


# A top-level type declaration (Kotlin or Java): at the start of a line, after annotations and modifiers.
TYPE_DECLARATION = re.compile(
    r"^(?:@[\w.]+(?:\([^)\n]*\))?\s+)*"
    r"(?:(?:public|internal|private|protected|data|sealed|abstract|open|enum|value|annotation|fun|inline|final|static|expect|actual)\s+)*"
    r"(?:class|interface|object|typealias)\s+([A-Z]\w*)",
    re.M,
)


@dataclass
class Rules:
    allowed: dict[str, set[str]]                                         # module -> modules its main code may use
    double_prefixes: tuple[str, ...] = ()                                # a type named so is a test double
    test_code_modules: set[str] = field(default_factory=set)             # modules whose main code is test code
    doubles_allowed: set[str] = field(default_factory=set)               # double-like names main code may hold
    shared_names_allowed: set[str] = field(default_factory=set)          # names more than one type may have


def table_rows(text: str, heading: str) -> list[list[str]]:
    """The cells of every table row (header and rule rows aside) in the sections whose heading holds
    [heading] (case-insensitive), up to the next heading."""
    rows, inside = [], False
    for line in text.splitlines():
        if line.startswith("#"):
            inside = heading in line.lower()
            continue
        if inside and line.startswith("|") and not re.match(r"^\|[\s|:-]+\|\s*$", line):
            rows.append([c.strip() for c in line.strip().strip("|").split("|")])
    return rows[1:] if rows else rows  # the first row is the table's header


def quoted(cell: str) -> list[str]:
    return re.findall(r"`([^`]+)`", cell)


def read_rules(root: str) -> Rules:
    """The 'Who may use whom' table of docs/architecture.md: rows whose first cell is a `:module`."""
    with open(os.path.join(root, DOC), encoding="utf-8") as f:
        text = f.read()
    allowed: dict[str, set[str]] = {}
    section = None
    for line in text.splitlines():
        if line.startswith("#"):
            section = "deps" if "who may use whom" in line.lower() else None
            continue
        if not line.startswith("|") or section is None:
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        first = re.findall(r"`([^`]+)`", cells[0])
        if first and first[0].startswith(":"):
            allowed[first[0]] = set(re.findall(r"`(:[\w:-]+)`", cells[1] if len(cells) > 1 else ""))
    if not allowed:
        raise ValueError(f"{DOC} has no 'Who may use whom' table")
    rules = Rules(allowed)
    for row in table_rows(text, "test doubles stay in tests"):
        what = row[0].lower()
        values = quoted(row[1]) if len(row) > 1 else []
        if what.startswith("double prefixes"):
            rules.double_prefixes = tuple(values)
        elif what.startswith("modules whose main code is test code"):
            rules.test_code_modules = set(values)
        elif quoted(row[0]):
            rules.doubles_allowed.update(quoted(row[0]))
    for row in table_rows(text, "one type per name"):
        rules.shared_names_allowed.update(quoted(row[0]))
    return rules


def declared_types(text: str) -> list[str]:
    """The simple names of the top-level types [text] declares (nested types are indented, so not matched)."""
    return TYPE_DECLARATION.findall(re.sub(r"/\*.*?\*/", " ", text, flags=re.S))


def is_double(name: str, prefixes: tuple[str, ...]) -> bool:
    """Whether [name] starts with one of [prefixes] followed by a capital (`TestIcons`, not `Testament`)."""
    return any(name.startswith(p) and name[len(p):][:1].isupper() for p in prefixes)


def modules(root: str) -> dict[str, str]:
    """`:path` -> directory, from settings.gradle.kts."""
    with open(os.path.join(root, "settings.gradle.kts"), encoding="utf-8") as f:
        paths = re.findall(r'(?m)^\s*include\("(:[\w:-]+)"\)', f.read())
    return {p: os.path.join(root, *p.strip(":").split(":")) for p in paths}


def main_files(directory: str) -> list[str]:
    found = []
    for sources in MAIN_SOURCES:
        for d, _, files in os.walk(os.path.join(directory, sources)):
            found += [os.path.join(d, f) for f in files if f.endswith((".kt", ".java"))]
    return sorted(found)


def main_project_deps(directory: str) -> set[str]:
    """The module's project dependencies outside the test configurations."""
    with open(os.path.join(directory, "build.gradle.kts"), encoding="utf-8") as f:
        text = re.sub(r"//[^\n]*", "", f.read())
    return {path for conf, path in PROJECT_DEP.findall(text) if not conf.lower().startswith(("test", "androidtest"))}


def generated_classes(directory: str) -> tuple[str, ...]:
    """The classes the Android build generates in the module's `namespace` (none for a plain JVM module)."""
    with open(os.path.join(directory, "build.gradle.kts"), encoding="utf-8") as f:
        m = NAMESPACE.search(f.read())
    return (f"{m.group(1)}.R", f"{m.group(1)}.BuildConfig") if m else ()


def is_generated(name: str, generated: tuple[str, ...]) -> bool:
    """Whether [name] is one of the [generated] classes or a member of one (`org.x.R.drawable.icon`)."""
    return any(name == g or name.startswith(g + ".") for g in generated)


def feature_of(pkg: str) -> str | None:
    """The feature a package belongs to (`org.x.app.feature.chat` for it and its subpackages), or None."""
    parts = pkg.split(".")
    if "feature" not in parts[:-1]:
        return None
    i = parts.index("feature")
    return ".".join(parts[: i + 2])


def owner(imported: str, packages: dict[str, str]) -> tuple[str, str] | None:
    """(module, package) declaring the longest package prefix of [imported], or None (a library)."""
    parts = imported.split(".")
    for i in range(len(parts), 0, -1):
        pkg = ".".join(parts[:i])
        if pkg in packages:
            return packages[pkg], pkg
    return None


def cycles(graph: dict[str, set[str]]) -> list[set[str]]:
    """Strongly connected components of more than one package (Tarjan, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[set[str]] = []
    counter = 0
    for start in sorted(graph):
        if start in index:
            continue
        work = [(start, iter(sorted(graph.get(start, ()))))]
        index[start] = low[start] = counter
        counter += 1
        stack.append(start)
        on_stack.add(start)
        while work:
            node, successors = work[-1]
            advanced = False
            for nxt in successors:
                if nxt not in index:
                    index[nxt] = low[nxt] = counter
                    counter += 1
                    stack.append(nxt)
                    on_stack.add(nxt)
                    work.append((nxt, iter(sorted(graph.get(nxt, ())))))
                    advanced = True
                    break
                if nxt in on_stack:
                    low[node] = min(low[node], index[nxt])
            if advanced:
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = set()
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.add(member)
                    if member == node:
                        break
                if len(component) > 1:
                    found.append(component)
    return found


def check(root: str) -> list[str]:
    rules = read_rules(root)
    mods = modules(root)
    violations: list[str] = []
    for path in mods:
        if path not in rules.allowed:
            violations.append(f"{path}: not in {DOC}'s 'Who may use whom' table")

    # Which module declares each package (main sources only).
    packages: dict[str, str] = {}
    sources: dict[str, list[tuple[str, str, str]]] = {}    # module -> (file, package, text)
    for path, directory in mods.items():
        sources[path] = []
        for file in main_files(directory):
            with open(file, encoding="utf-8") as f:
                text = f.read()
            m = PACKAGE.search(text)
            pkg = m.group(1) if m else ""
            sources[path].append((file, pkg, text))
            packages.setdefault(pkg, path)

    roots = {pkg.split(".", 1)[0] for pkg in packages if pkg}
    for path, directory in mods.items():
        allowed = rules.allowed.get(path, set()) | {path}
        for dep in sorted(main_project_deps(directory) - allowed):
            build_file = os.path.relpath(os.path.join(directory, "build.gradle.kts"), root)
            violations.append(f"{build_file}: main code depends on {dep}, which {DOC} does not allow")
        generated = generated_classes(directory)
        graph: dict[str, set[str]] = {}
        for file, pkg, text in sources[path]:
            graph.setdefault(pkg, set())
            for imported in used_names(text, roots):
                found = owner(imported, packages)
                if found is None:
                    continue
                module, imported_pkg = found
                rel = os.path.relpath(file, root)
                if module not in allowed:
                    violations.append(f"{rel}: imports {imported} from {module}, which {DOC} does not allow for {path}")
                elif module == path and imported_pkg != pkg and not is_generated(imported, generated):
                    graph[pkg].add(imported_pkg)
                    mine, theirs = feature_of(pkg), feature_of(imported_pkg)
                    if mine and theirs and mine != theirs:
                        violations.append(f"{rel}: feature {mine} imports {imported} from feature {theirs}; features do not import each other")
                    elif mine and imported_pkg.split(".")[-1] == "di":
                        violations.append(f"{rel}: feature {mine} imports {imported}; a route takes what it uses, not the container")
        for component in cycles(graph):
            violations.append(f"{path}: packages import each other in a cycle: {', '.join(sorted(component))}")
    return violations + type_violations(root, rules, sources)


def type_violations(root: str, rules: Rules, sources: dict[str, list[tuple[str, str, str]]]) -> list[str]:
    """Test doubles in main code, and simple names more than one top-level type of main code has."""
    violations: list[str] = []
    where: dict[str, list[str]] = {}
    for path, files in sources.items():
        for file, _, text in files:
            rel = os.path.relpath(file, root).replace(os.sep, "/")
            for name in declared_types(text):
                where.setdefault(name, []).append(rel)
                if path in rules.test_code_modules or name in rules.doubles_allowed:
                    continue
                if is_double(name, rules.double_prefixes):
                    violations.append(f"{rel}: test double {name} in the main code of {path}: move it to its tests or :test-fixtures")
    for name, files in sorted(where.items()):
        if len(files) > 1 and name not in rules.shared_names_allowed:
            violations.append(f"{len(files)} types of main code named {name}: {', '.join(sorted(files))}; give each a name of its own")
    return violations
