"""The child process that compiles one xacro file, behind resource limits and three fences.

xacro evaluates ``${...}`` and ``$(eval ...)`` as Python: compiling a xacro file runs the
file's author's code. :func:`solver.identify.xacro.compiler.compile_xacro` therefore never
compiles in the caller's process. It starts this module in a fresh interpreter (``python -I -S
-B``, an empty environment) and sends one JSON request on stdin; this module, in this order,

1. lowers its own limits: CPU seconds, address space, no file writes (``RLIMIT_FSIZE`` 0), a
   handful of open files, no core file;
2. refuses system calls in the kernel (:func:`~solver.identify.xacro.confine.forbid_system_calls`:
   no process, socket, file write or metadata change, nothing in another process), before
   xacro is even imported;
3. loads xacro and everything it imports lazily (a small warm-up document), then replaces
   xacro's evaluators with guarded ones (:mod:`solver.identify.xacro.expressions`: no module,
   frame or code object reachable from an expression);
4. lets the kernel allow reads only beneath the description's package folders
   (:func:`~solver.identify.xacro.confine.restrict_reads`, Landlock), drops ctypes, and
   replaces ``open`` with a fence that reads regular files inside those folders only, each
   through the size cap and the safe-XML check; no module may be imported from then on;
5. never reads the environment (the robot's author does not get to read the operator's):
   ``$(env NAME)`` takes the value of the xacro argument ``NAME`` (``--arg NAME:=VALUE``) and
   is refused without one; ``$(optenv NAME DEFAULT)`` takes that argument, else its default
   (as xacro does with the variable unset); ``$(find pkg)`` resolves only from the package map
   it was given;
6. only then reads the user's file and compiles it, answering with one JSON object on stdout:
   the URDF text and xacro's warnings, or an error message with the file and line it concerns.

What ``--trust-xacro`` guarantees, and where each fence is missing, is documented in
docs/security.md.

Not here: starting the process, the wall-clock timeout and reading its answer
(:mod:`solver.identify.xacro.compiler`).
"""

from __future__ import annotations

import builtins
import contextlib
import io
import json
import os
import re
import resource
import sys
from collections.abc import Callable, Iterator, Mapping, Sequence
from pathlib import Path
from typing import Any

from solver.errors import SolverError
from solver.identify.xacro import expressions, legacy
from solver.identify.xacro.confine import (
    Confinement,
    forbid_system_calls,
    forget_ctypes,
    restrict_reads,
)

__all__ = ["main"]

# Each input file is read with the same cap the parent uses for the description itself.
_MAX_FILE_BYTES = 16 * 1024 * 1024
_OPEN_FILES = 64
_FILE_LINE = re.compile(r"\[?(?:in file|when processing file):?\s*(\S+?)\]?(?:\s|$)")


class Refused(Exception):
    """A file or lookup the fence does not allow; reported as the compile error."""


def main() -> None:
    request = json.loads(sys.stdin.read(4 * _MAX_FILE_BYTES))
    _limit(request["cpu_seconds"], request["memory_bytes"])
    seccomp = forbid_system_calls()
    sys.setrecursionlimit(4000)
    try:
        answer: dict[str, Any] = {"ok": True, **_compile(request, seccomp=seccomp)}
    except MemoryError:
        answer = {
            "ok": False,
            "message": "xacro used more memory than the limit allows "
            f"({request['memory_bytes'] // 2**20} MiB)",
            "code": "xacro-limit",
        }
    except RecursionError:
        answer = {"ok": False, "message": "xacro: macro recursion too deep", "code": "xacro"}
    except SolverError as error:  # the safe-XML check of an included file: keep its location
        fault = error.faults[0]
        answer = {
            "ok": False,
            "code": fault.code,
            "message": fault.message,
            "file": fault.location.file,
            "line": fault.location.line,
        }
    except Exception as error:  # every other failure is the input's; it becomes a message
        answer = {"ok": False, "code": "xacro", **_describe(error)}
    text = json.dumps(answer)
    sys.stdout.write(text)
    sys.stdout.flush()


def _limit(cpu_seconds: int, memory_bytes: int) -> None:
    resource.setrlimit(resource.RLIMIT_CPU, (cpu_seconds, cpu_seconds))
    resource.setrlimit(resource.RLIMIT_AS, (memory_bytes, memory_bytes))
    resource.setrlimit(resource.RLIMIT_FSIZE, (0, 0))
    resource.setrlimit(resource.RLIMIT_NOFILE, (_OPEN_FILES, _OPEN_FILES))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))


def _compile(request: dict[str, Any], *, seccomp: bool) -> dict[str, Any]:
    source = request["source"]
    roots = tuple(Path(r) for r in request["roots"])
    packages: dict[str, str] = request["packages"]
    fence = _Fence(roots, seccomp=seccomp)
    with fence.installed():
        import xacro
        from xacro import substitution_args

        given: dict[str, str] = dict(request["args"])

        def env(name: str) -> str:
            """``$(env NAME)``: the value ``--arg NAME:=VALUE`` gives, never the environment."""
            if name in given:
                return given[name]
            raise Refused(
                f"$(env {name}): environment lookups are refused; "
                f"pass the value with --arg {name}:=VALUE"
            )

        def optenv(name: str, default: str = "") -> str:
            """``$(optenv NAME DEFAULT)``: ``--arg NAME:=VALUE``, else the default, as xacro
            does with the variable unset (the environment is never read)."""
            return given.get(name, default)

        def find(package: str) -> str:
            folder = packages.get(package)
            if folder is None:
                raise Refused(f"Package not found: {package}")
            return folder

        substitution_args._eval_env = env
        substitution_args._eval_optenv = optenv
        substitution_args._eval_find = find
        substitution_args._eval_dict.update(env=env, optenv=optenv, find=find)
        captured = io.StringIO()
        with contextlib.redirect_stderr(captured):
            xacro.init_stacks(source)
            document = xacro.parse(fence.read_text(source))
            xacro.process_doc(document, mappings=dict(request["args"]))
            text = document.toxml()
    if len(text.encode("utf-8")) > _MAX_FILE_BYTES:
        raise Refused(f"xacro output is larger than {_MAX_FILE_BYTES} bytes; refused")
    warnings = fence.flaws + [
        line.strip() for line in captured.getvalue().splitlines() if line.strip()
    ]
    missing = fence.confinement.missing
    if missing:
        warnings.insert(
            0,
            f"this system gave no {' and no '.join(missing)}: the file was "
            "compiled with fewer fences (docs/security.md)",
        )
    return {"text": text, "warnings": warnings[:100]}


def _describe(error: BaseException) -> dict[str, Any]:
    message = str(error).strip() or type(error).__name__
    exc = getattr(error, "exc", None)
    if isinstance(exc, BaseException) and not str(error).strip():
        message = str(exc).strip() or type(exc).__name__
    elif isinstance(exc, MemoryError):  # xacro wraps it: "when evaluating expression ..." alone
        message = f"out of memory (the limit for xacro) {message}"
    elif isinstance(exc, BaseException) and str(exc).strip() not in message:
        message = f"{str(exc).strip() or type(exc).__name__}: {message}"
    elif isinstance(exc, BaseException) and error.args and str(exc) in str(error.args[0]):
        # xacro's "<class 'E'>: text" message already holds the cause it appends once more
        suffix = str(getattr(error, "suffix", None) or "")
        message = re.sub(r"^<class '(\w+)'>: ", r"\1: ", f"{error.args[0]} {suffix}".strip())
    found = _FILE_LINE.search(message)
    return {"message": message[:2000], "file": found.group(1) if found else None}


class _Fence:
    """``open`` for reading regular files inside ``roots``, through the caps; nothing else."""

    def __init__(self, roots: tuple[Path, ...], *, seccomp: bool) -> None:
        self.roots = tuple(root.resolve() for root in roots)
        self._open: Callable[..., Any] = builtins.open
        self.confinement = Confinement(0, seccomp=seccomp)
        self.flaws: list[str] = []  # what the lenient parse of each file read past

    def check(self, file: str | os.PathLike[str]) -> Path:
        path = Path(os.fspath(file))
        resolved = path.resolve()
        if not any(resolved.is_relative_to(root) for root in self.roots):
            raise Refused(f"{os.fspath(file)}: outside the description's package folders; refused")
        if not resolved.exists():
            raise Refused(f"{os.fspath(file)}: no such file")
        if not resolved.is_file():
            raise Refused(f"{os.fspath(file)}: not a regular file; refused")
        return resolved

    def read_bytes(self, file: str | os.PathLike[str]) -> bytes:
        resolved = self.check(file)
        with self._open(resolved, "rb") as handle:
            data: bytes = handle.read(_MAX_FILE_BYTES + 1)
        if len(data) > _MAX_FILE_BYTES:
            raise Refused(f"{os.fspath(file)}: larger than {_MAX_FILE_BYTES} bytes; refused")
        return data

    def read_text(self, file: str | os.PathLike[str]) -> str:
        from solver.errors import Fault
        from solver.identify.readers.safexml import parse_xml

        data = self.read_bytes(file)
        if not os.fspath(file).endswith((".yaml", ".yml")):
            flaws: list[Fault] = []
            parse_xml(data, os.fspath(file), warnings=flaws)  # entity bombs and DTDs stop here
            self.flaws += [str(flaw) for flaw in flaws]
        return data.decode("utf-8")

    def fenced_open(self, file: Any, mode: str = "r", *_: Any, **__: Any) -> Any:
        if isinstance(file, int) or any(flag in mode for flag in "wax+"):
            raise Refused(f"{file!r}: xacro may only read files; refused")
        text = self.read_text(file)
        return io.BytesIO(text.encode("utf-8")) if "b" in mode else io.StringIO(text)

    @contextlib.contextmanager
    def installed(self) -> Iterator[None]:
        # Everything xacro imports lazily is loaded now, by a small warm-up document run
        # through the guarded evaluators: once the fence is up, no module may be imported.
        import xml.dom.expatbuilder
        import xml.dom.minidom

        import lxml.etree  # noqa: F401
        import xacro
        import xacro.substitution_args
        import yaml

        from solver.identify.readers.safexml import parse_xml

        expressions.install(xacro, xacro.substitution_args)
        legacy.install(xacro)
        warm_up = (
            '<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:property '
            'name="p" value="${1 + 1}"/><xacro:macro name="m" params="x"><link '
            'name="l${x}" type="$(eval 2 * 2)"/></xacro:macro><xacro:m x="${p}"/></robot>'
        )
        xacro.init_stacks(None)
        xacro.process_doc(xacro.parse(warm_up))
        yaml.safe_load("a: [1, 2.5, b]")
        parse_xml(warm_up.encode(), "<warm-up>", warnings=[])
        xml.dom.minidom.parseString(warm_up).toxml()

        # Reads beneath the roots only from now on (Landlock); the system calls were refused
        # before xacro was imported (seccomp, in main). The kernel holds what the Python-level
        # fence below cannot promise alone.
        abi = restrict_reads(self.roots)
        forget_ctypes()
        self.confinement = Confinement(abi, self.confinement.seccomp)
        builtins.open = self.fenced_open
        io.open = self.fenced_open
        _disarm()
        yield


def _refused(*_: object, **__: object) -> Any:
    raise Refused("xacro may not start processes, write files or import modules; refused")


def _disarm() -> None:
    """Take away what an expression that escaped xacro's namespace would reach for first.

    Defence in depth for a file the user chose to trust, not a sandbox: the process is about
    to end anyway, so nothing is restored.
    """
    import _io
    import posix

    for module in (os, posix):
        for name in (
            "system",
            "popen",
            "fork",
            "forkpty",
            "execv",
            "execve",
            "execvp",
            "execvpe",
            "execl",
            "execle",
            "execlp",
            "execlpe",
            "spawnv",
            "spawnve",
            "spawnvp",
            "spawnvpe",
            "spawnl",
            "spawnle",
            "posix_spawn",
            "posix_spawnp",
            "open",
            "remove",
            "unlink",
            "rename",
            "replace",
            "rmdir",
            "mkdir",
            "symlink",
            "link",
            "truncate",
            "chmod",
            "chown",
            "kill",
            "killpg",
        ):
            if hasattr(module, name):
                setattr(module, name, _refused)
    _io.FileIO = _refused  # type: ignore[misc, assignment]  # no unfenced file objects
    io.FileIO = _refused  # type: ignore[misc, assignment]  # the same class, by its other name
    sys.modules["_posixsubprocess"] = None  # type: ignore[assignment]  # None blocks the import
    sys.modules["subprocess"] = None  # type: ignore[assignment]  # None blocks the import
    sys.modules["ctypes"] = None  # type: ignore[assignment]  # None blocks the import
    loaded = set(sys.modules)
    original = builtins.__import__

    def frozen_import(
        name: str,
        globals: Mapping[str, Any] | None = None,
        locals: Mapping[str, Any] | None = None,
        fromlist: Sequence[str] = (),
        level: int = 0,
    ) -> Any:
        full = name
        if level:  # a relative import names its module from the importing package
            package = str((globals or {}).get("__package__") or "")
            base = package.rsplit(".", level - 1)[0] if level > 1 else package
            full = f"{base}.{name}" if name else base
        if full not in loaded:
            raise Refused(f"import {full}: xacro may not import modules; refused")
        return original(name, globals, locals, fromlist, level)

    builtins.__import__ = frozen_import  # type: ignore[assignment]  # typeshed's is narrower


if __name__ == "__main__":
    main()
