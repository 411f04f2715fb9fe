"""Every ``module.name`` that the project's code reads names something the module has.

A misspelt attribute of an imported module (``os.cpucount_lines()``, left by a text
replacement) raises only when its line runs; in a benchmark's ``main`` or an error
path that may be never in the suite. This test reads each source file of ``app/``,
``bench/`` and ``backend_sim/``, finds the names bound to modules by its top-level
imports (``import os``, ``from . import bulk``) and checks each attribute read from
them exists (or is a submodule)."""

import ast
import importlib
import importlib.util
import types
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SOURCES = sorted(p for folder in ("app", "bench", "backend_sim") for p in (ROOT / folder).rglob("*.py"))


def _package(path: Path) -> str:
    parts = path.relative_to(ROOT).with_suffix("").parts
    return ".".join(parts if path.name == "__init__.py" else parts[:-1]).removesuffix(".__init__")


def _module(name: str) -> types.ModuleType | None:
    try:
        return importlib.import_module(name)
    except Exception:  # (a module this machine cannot import: nothing to check against)
        return None


def _imported_modules(tree: ast.Module, path: Path) -> dict[str, types.ModuleType]:
    """Top-level names bound to modules by the file's imports."""
    found = {}
    for node in tree.body:
        if isinstance(node, ast.Import):
            for alias in node.names:
                name = alias.name if alias.asname else alias.name.split(".")[0]
                module = _module(name)
                if module is not None:
                    found[alias.asname or name] = module
        elif isinstance(node, ast.ImportFrom):
            base = importlib.util.resolve_name("." * node.level + (node.module or ""), _package(path)) \
                if node.level else node.module
            for alias in node.names:
                module = _module(f"{base}.{alias.name}")
                if module is not None:
                    found[alias.asname or alias.name] = module
    return found


def _missing(module: types.ModuleType, attribute: str) -> bool:
    return not hasattr(module, attribute) and _module(f"{module.__name__}.{attribute}") is None


def test_every_attribute_read_from_an_imported_module_exists():
    wrong = []
    for path in SOURCES:
        tree = ast.parse(path.read_text(encoding="utf-8"), str(path))
        modules = _imported_modules(tree, path)
        rebound = {n.id for n in ast.walk(tree)
                   if isinstance(n, ast.Name) and not isinstance(n.ctx, ast.Load)}  # (a name reassigned)
        for node in ast.walk(tree):
            if (isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Load)
                    and isinstance(node.value, ast.Name) and node.value.id in modules
                    and node.value.id not in rebound and _missing(modules[node.value.id], node.attr)):
                wrong.append(f"{path.relative_to(ROOT)}:{node.lineno}: {node.value.id}.{node.attr}")
    assert not wrong, "attributes no module has:\n" + "\n".join(wrong)


def test_the_check_finds_a_misspelt_attribute():
    tree = ast.parse("import os\nprint(os.cpucount_lines())\n")
    modules = _imported_modules(tree, ROOT / "bench" / "example.py")
    assert _missing(modules["os"], "cpucount_lines") and not _missing(modules["os"], "cpu_count")
