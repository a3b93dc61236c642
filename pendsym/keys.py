"""Content keys: what each Result depends on, hashed, so that derive redoes only what changed.

A Result's key covers exactly:
* the source of its section and of every module of the engine or of its memoir that the
  section imports, transitively (found by reading the import statements, never by running them);
* the engine's spine (records, registry, verification, the check engine, the pipeline),
  which decides every status and every piece of evidence;
* the keys of the Results it depends on;
* the versions of SymPy and mpmath.
A kernel's key adds the emitter's source (``pendsym/emit``).  The whole tree's key (:func:`tree_key`)
covers every source file and is what a no-op derive compares, without importing any memoir.
"""
from __future__ import annotations

import ast
import hashlib
import importlib.util
from functools import lru_cache
from importlib import metadata
from pathlib import Path
from typing import Iterable, Mapping

SPINE = ("pendsym.result", "pendsym.registry", "pendsym.memoir", "pendsym.verify", "pendsym.checks",
         "pendsym.pipeline")
EMITTER = "pendsym.emit"   # the kernels of a Result also depend on these emitters
FORMAT = "1"   # bump when the meaning of a cached value changes


def digest(parts: Iterable[bytes | str]) -> str:
    h = hashlib.sha256()
    for p in parts:
        h.update(p.encode() if isinstance(p, str) else p)
        h.update(b"\0")
    return h.hexdigest()


@lru_cache(maxsize=1)
def versions() -> tuple[str, ...]:
    """The versions of the packages that shape every derived form and every digit of evidence."""
    return tuple(f"{name}=={metadata.version(name)}" for name in ("sympy", "mpmath"))


@lru_cache(maxsize=None)
def module_file(name: str) -> Path | None:
    """The source file of a module (its __init__.py for a package), without importing it."""
    try:
        spec = importlib.util.find_spec(name)
    except (ImportError, ValueError):
        return None
    if spec is None or not spec.origin or not spec.origin.endswith(".py"):
        return None
    return Path(spec.origin)


def _is_package(path: Path) -> bool:
    return path.name == "__init__.py"


@lru_cache(maxsize=None)
def imports_of(name: str, roots: tuple[str, ...]) -> tuple[str, ...]:
    """The modules under the given top-level packages that module ``name`` imports (one level)."""
    path = module_file(name)
    if path is None:
        return ()
    tree = ast.parse(path.read_bytes(), filename=str(path))
    package = name if _is_package(path) else name.rpartition(".")[0]
    found: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parts = package.split(".")
                parent = ".".join(parts[: len(parts) - node.level + 1])
                base = f"{parent}.{base}" if base else parent
            for alias in node.names:   # `from pkg import module` imports the module, not pkg's __init__
                sub = f"{base}.{alias.name}"
                found.add(sub if module_file(sub) is not None else base)
    return tuple(sorted(m for m in found if m.split(".")[0] in roots and module_file(m) is not None))


@lru_cache(maxsize=None)
def closure(name: str, roots: tuple[str, ...]) -> tuple[str, ...]:
    """Module ``name`` and every module under ``roots`` it imports, transitively."""
    seen: set[str] = set()
    stack = [name]
    while stack:
        mod = stack.pop()
        if mod in seen:
            continue
        seen.add(mod)
        stack.extend(imports_of(mod, roots))
    return tuple(sorted(seen))


@lru_cache(maxsize=None)
def file_hash(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def modules_hash(names: Iterable[str]) -> str:
    """Hash of the sources of the modules (by name and content)."""
    return digest(f"{n}:{file_hash(module_file(n))}" for n in sorted(set(names)))


def section_hash(module: str, roots: tuple[str, ...]) -> str:
    """The section's source and everything under ``roots`` it imports, plus the spine."""
    return modules_hash(closure(module, roots) + tuple(m for s in SPINE for m in closure(s, ("pendsym",))))


def result_keys(sections: Mapping[str, str], deps: Mapping[str, tuple[str, ...]], order: Iterable[str],
                roots: tuple[str, ...]) -> dict[str, str]:
    """Key of every Result: ``sections`` maps an id to its section module, ``deps`` to its
    dependencies, ``order`` lists the ids dependencies first."""
    by_section: dict[str, str] = {}
    out: dict[str, str] = {}
    for rid in order:
        mod = sections[rid]
        if mod not in by_section:
            by_section[mod] = section_hash(mod, roots)
        out[rid] = digest((FORMAT, *versions(), rid, by_section[mod], *(out[d] for d in deps[rid])))
    return out


def emitter_hash() -> str:
    """The kernel emitters' source: forms, printers, file layout and the kernels' templates (not the
    report's, which shape no kernel)."""
    root = module_file(EMITTER).parent
    templates = module_file("pendsym").parent / "templates"
    files = sorted([*(root / "kernels").rglob("*.py"), root / "files.py", root / "layout.py",
                    *(t for t in templates.glob("*.j2") if not t.name.startswith("report"))])
    return digest(f"{f.relative_to(root.parent)}:{file_hash(f)}" for f in files if f.exists())


def tree_key(packages: Iterable[str], *extra: str) -> str:
    """Key of the whole tree: every source file of the engine and of the memoir packages, the
    versions, and ``extra`` (e.g. the level).  Computed without importing any memoir."""
    files = []
    for pkg in ("pendsym", *packages):
        init = module_file(pkg)
        if init is None:
            continue
        root = init.parent
        files += [(f"{pkg}/{f.relative_to(root)}", f) for f in root.rglob("*")
                  if f.suffix in (".py", ".j2") and "__pycache__" not in f.parts]
    return digest((FORMAT, *versions(), *extra, *(f"{rel}:{file_hash(f)}" for rel, f in sorted(files))))
