"""Reading user files and quoting user values (bounded, strict, clear errors); hltl's caches."""

from __future__ import annotations

import json
import os
import re
import reprlib
import threading
from collections.abc import Callable
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any

from hltl.errors import HltlError, OutputError

# CPython's own SHA-256 (hashlib's fallback): the same digests without hashlib, which loads
# OpenSSL's libcrypto (~3 ms of every start-up, docs/planner.md "Start-up"); `random` takes its
# _sha512 the same way
if TYPE_CHECKING:
    from hashlib import sha256 as sha256
else:
    try:
        from _sha256 import sha256
    except ImportError:  # (Python 3.12 and later name it _sha2)
        from hashlib import sha256

if TYPE_CHECKING:
    import yaml
    from yaml.nodes import Node

# Scenes, specs and events are a few kilobytes; a megabyte-sized one is a mistake or an attack,
# and everything downstream (messages, the planner) scales with it. Logs grow with the episode.
MAX_INPUT_BYTES = 1 << 20
MAX_LOG_BYTES = 64 << 20
# An alias expands to a copy of what it names, so a few hundred bytes of YAML can stand for
# millions of nodes (the "billion laughs"); the budget counts every expanded node.
MAX_YAML_NODES = 100_000
# Nesting deeper than this is no scene, spec or events file; it also keeps recursive
# composition and validation far from Python's recursion limit.
MAX_NESTING = 64
# Values quoted in error messages show their start and their length beyond this.
QUOTE_LIMIT = 80

ErrorType = Callable[[str], HltlError]


def quote(value: Any, limit: int = QUOTE_LIMIT) -> str:
    """``repr(value)`` cut to about ``limit`` characters; a long string shows its start and length.

    Error messages quote what the user gave; a 10,000-word instruction or a 200 MB list must not
    become a 200 MB error line.
    """
    if isinstance(value, str | bytes):
        if len(value) <= limit:
            return repr(value)
        unit = "characters" if isinstance(value, str) else "bytes"
        return f"{value[:limit]!r}… ({len(value):,} {unit})"
    # reprlib bounds containers level by level without rendering them whole first
    text = _REPR.repr(value)
    return text if len(text) <= limit else text[:limit] + "…"


_REPR = reprlib.Repr()
for _name in ("maxlist", "maxtuple", "maxdict", "maxset", "maxfrozenset", "maxdeque", "maxarray"):
    setattr(_REPR, _name, 8)
_REPR.maxlevel = 3
_REPR.maxstring = 40
_REPR.maxother = 40


def clip(text: str, limit: int = 300) -> str:
    """``text`` itself when short, else its start and its length (for messages, not values)."""
    return text if len(text) <= limit else f"{text[:limit]}… ({len(text):,} characters)"


def read_text(path: str | Path, what: str, error: ErrorType, limit: int = MAX_INPUT_BYTES) -> str:
    """The UTF-8 text of a file the user named, or ``error`` with a message naming the file.

    Args:
        path: the file.
        what: what the file should be ("scene file", "events file", …), for the message.
        error: the exception type to raise (the caller's domain error).
        limit: the most bytes read.

    Raises:
        HltlError: of type ``error``: unreadable, larger than ``limit``, or not UTF-8.
    """
    p = Path(path)
    try:
        with p.open("rb") as fh:
            data = fh.read(limit + 1)
    except OSError as exc:
        raise error(f"{p}: cannot read {what}: {exc.strerror or exc}") from None
    if len(data) > limit:
        raise error(f"{p}: {what} is larger than {limit:,} bytes; is it the right file?")
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = data[: exc.start].count(b"\n") + 1
        raise error(
            f"{p}: {what} is not UTF-8 text (byte 0x{data[exc.start]:02x} at line {line}, "
            f"offset {exc.start}); save it as UTF-8"
        ) from None


def load_data(text: str, source: str, error: ErrorType, *, as_json: bool) -> Any:
    """Parse YAML (or JSON) strictly: no duplicate keys, bounded aliases and nesting.

    YAML follows 1.2 where 1.1 surprises: ``1e3`` and ``1.0e300`` are numbers, as in JSON.

    Raises:
        HltlError: of type ``error``, starting with ``source``.
    """
    if as_json:
        return _load_json(text, source, error)
    import yaml  # (imported here: ~15 ms of start-up, and a cached file needs none, load_file)

    loader: yaml.SafeLoader | None = None
    try:
        loader = _strict_loader()(text)  # reads (and may refuse) the first characters already
        return loader.get_single_data()
    except _Refused as exc:
        raise error(f"{source}: {exc}") from None
    except yaml.YAMLError as exc:
        raise error(f"{source}: not valid YAML: {_bounded_yaml_error(exc)}") from None
    finally:
        if loader is not None:
            loader.dispose()


def load_file(path: str | Path, what: str, error: ErrorType, limit: int = MAX_INPUT_BYTES) -> Any:
    """:func:`read_text` then :func:`load_data` (JSON for ``.json`` files, else YAML).

    A YAML file read before is read from its JSON copy in ``cache_dir("yaml")`` (keyed by the
    text), which neither imports nor runs PyYAML: :func:`yaml_cached`.
    """
    p = Path(path)
    text = read_text(p, what, error, limit)
    if p.suffix.lower() == ".json":
        return load_data(text, str(p), error, as_json=True)
    return yaml_cached(text, str(p), error)


# A cached file's data must be what the YAML loader gives for its text: the key names this
# format and hashes this module's own source (a change to the loader's rules starts afresh).
YAML_CACHE_FORMAT = 1
# Scenes and specs are a few kilobytes; a large YAML text is read as usual, not stored.
YAML_CACHE_MAX_CHARS = 64 << 10
_own_source: bytes | None = None


def yaml_cached(text: str, source: str, error: ErrorType) -> Any:
    """:func:`load_data` of a YAML ``text``, kept as JSON in ``cache_dir("yaml")``: a text read
    before (by any process) is read back with ``json`` (a tenth of a millisecond against ~15 ms
    to import PyYAML and ~3 ms to parse a scene). Only data JSON gives back unchanged is kept:
    maps with string keys, lists, strings, numbers, booleans and null, without a shared part
    (an alias); errors are never kept, so a refused text is refused again with its message.
    """
    global _own_source
    folder = cache_dir("yaml")
    if folder is None or len(text) > YAML_CACHE_MAX_CHARS:
        return load_data(text, source, error, as_json=False)
    if _own_source is None:
        try:
            _own_source = Path(__file__).read_bytes()
        except OSError:
            return load_data(text, source, error, as_json=False)
    digest = sha256(_own_source)
    digest.update(f"\n{YAML_CACHE_FORMAT}\n{text}".encode())
    path = folder / f"{digest.hexdigest()}.json"
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        pass  # not kept yet (or damaged: read and kept again)
    data = load_data(text, source, error, as_json=False)
    if _json_exact(data):
        tmp = path.with_suffix(f".{os.getpid()}.{threading.get_ident()}.tmp")
        try:
            folder.mkdir(parents=True, exist_ok=True)
            tmp.write_text(json.dumps(data), encoding="utf-8")
            os.replace(tmp, path)  # atomic: another process never reads half a file
        except (OSError, ValueError):
            tmp.unlink(missing_ok=True)  # a read-only cache only costs the next read the parse
    return data


def _json_exact(data: Any) -> bool:
    """Whether ``json.loads(json.dumps(data)) == data`` with the same types, no part shared."""
    seen: set[int] = set()
    stack = [data]
    while stack:
        x = stack.pop()
        t = type(x)
        if t is dict:
            if id(x) in seen or any(type(k) is not str for k in x):
                return False
            seen.add(id(x))
            stack.extend(x.values())
        elif t is list:
            if id(x) in seen:
                return False
            seen.add(id(x))
            stack.extend(x)
        elif t not in (str, int, float, bool, type(None)):
            return False
    return True


def open_output(path: str | Path, what: str) -> IO[str]:
    """Open a file the user asked hltl to write (creating its folder), or a clear error.

    Raises:
        OutputError: the path is a folder, or it cannot be created or written.
    """
    p = Path(path)
    if p.is_dir():
        raise OutputError(f"{p}: cannot write {what}: it is a folder; give a file name")
    for parent in p.parents:
        if parent.exists() and not parent.is_dir():
            raise OutputError(f"{p}: cannot write {what}: {parent} is a file, not a folder")
    try:
        p.parent.mkdir(parents=True, exist_ok=True)
        return p.open("w", encoding="utf-8")
    except OSError as exc:
        raise OutputError(f"{p}: cannot write {what}: {exc.strerror or exc}") from None


def write_output(path: str | Path, what: str, text: str) -> None:
    """Write ``text`` to a file the user named, or raise :class:`OutputError`."""
    with open_output(path, what) as fh:
        try:
            fh.write(text)
        except OSError as exc:
            raise OutputError(f"{path}: cannot write {what}: {exc.strerror or exc}") from None


# -- strict JSON -----------------------------------------------------------------------------------


class _Refused(Exception):
    """A document that parses but is refused (duplicate key, too many nodes, too deep)."""


def _no_duplicates(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for key, value in pairs:
        if key in out:
            raise _Refused(f"duplicate key {quote(key)}; each key may appear once")
        out[key] = value
    return out


def try_json(text: str, source: str, error: ErrorType) -> tuple[bool, Any]:
    """``(True, value)`` when ``text`` is one JSON value, ``(False, None)`` when it is not JSON.

    Raises:
        HltlError: of type ``error``: JSON that is refused (duplicate keys, too deep).
    """
    try:
        return True, _load_json(text, source, error, sniff=True)
    except json.JSONDecodeError:
        return False, None


def _load_json(text: str, source: str, error: ErrorType, *, sniff: bool = False) -> Any:
    if _max_bracket_depth(text) > MAX_NESTING:
        raise error(f"{source}: nested more than {MAX_NESTING} levels deep")
    try:
        return json.loads(text, object_pairs_hook=_no_duplicates)
    except _Refused as exc:
        raise error(f"{source}: {exc}") from None
    except json.JSONDecodeError as exc:
        if sniff:
            raise
        raise error(
            f"{source}: not valid JSON: {exc.msg} at line {exc.lineno}, column {exc.colno}"
        ) from None


def _max_bracket_depth(text: str) -> int:
    # counts brackets inside strings too: an overestimate only for absurd strings, never an
    # underestimate, which is what a guard against deep recursion needs
    depth = best = 0
    for ch in text:
        if ch in "[{":
            depth += 1
            best = max(best, depth)
        elif ch in "]}":
            depth -= 1
    return best


# -- strict YAML -----------------------------------------------------------------------------------

_loader_lock = threading.Lock()
_loader: type[yaml.SafeLoader] | None = None


def _strict_loader() -> type[yaml.SafeLoader]:
    """SafeLoader that refuses duplicate keys, alias bombs and deep nesting, with YAML 1.2's
    floats (built on first use: PyYAML is imported only to read a YAML text)."""
    global _loader
    with _loader_lock:
        if _loader is None:
            _loader = _build_strict_loader()
        return _loader


def _build_strict_loader() -> type[yaml.SafeLoader]:
    import yaml
    from yaml.nodes import MappingNode, ScalarNode, SequenceNode

    # YAML 1.2's float syntax (JSON's, plus .inf/.nan): PyYAML follows YAML 1.1, which needs a dot
    # and a signed exponent, so it reads "1.0e300" and "1e3" as strings.
    float_12 = re.compile(
        r"""^(?:[-+]?(?:[0-9][0-9_]*)\.[0-9_]*(?:[eE][-+]?[0-9]+)?
        |[-+]?(?:[0-9][0-9_]*)(?:[eE][-+]?[0-9]+)
        |\.[0-9_]+(?:[eE][-+]?[0-9]+)?
        |[-+]?\.(?:inf|Inf|INF)
        |\.(?:nan|NaN|NAN))$""",
        re.X,
    )

    def _children(node: Node) -> list[Node]:
        if isinstance(node, SequenceNode):
            return list(node.value)
        if isinstance(node, MappingNode):
            return [n for pair in node.value for n in pair]
        return []

    class _StrictLoader(yaml.SafeLoader):
        """SafeLoader that refuses duplicate keys, alias bombs and deep nesting."""

        def __init__(self, stream: str) -> None:
            super().__init__(stream)
            self._budget = MAX_YAML_NODES
            self._depth = 0
            self._sizes: dict[int, int] = {}

        def compose_node(self, parent: Node | None, index: Any) -> Node | None:
            alias = self.check_event(yaml.AliasEvent)
            self._depth += 1
            try:
                if self._depth > MAX_NESTING:
                    raise _Refused(f"nested more than {MAX_NESTING} levels deep")
                node = super().compose_node(parent, index)
            finally:
                self._depth -= 1
            # an alias costs as many nodes as it expands to; anything else costs one
            self._budget -= self._size(node) if alias and node is not None else 1
            if self._budget < 0:
                raise _Refused(
                    f"the document expands to more than {MAX_YAML_NODES:,} values (through "
                    "anchors and aliases); write it out or make it smaller"
                )
            return node

        def _size(self, node: Node) -> int:
            # iterative and memoised: an alias tree shares its sub-nodes
            key = id(node)
            if key in self._sizes:
                return self._sizes[key]
            stack: list[tuple[Node, bool]] = [(node, False)]
            while stack:
                cur, ready = stack.pop()
                if id(cur) in self._sizes:
                    continue
                kids = _children(cur)
                if ready:
                    total = 1 + sum(self._sizes.get(id(k), 1) for k in kids)
                    self._sizes[id(cur)] = min(total, MAX_YAML_NODES + 1)
                    continue
                stack.append((cur, True))
                stack.extend((k, False) for k in kids if id(k) not in self._sizes)
            return self._sizes[key]

        def construct_mapping(self, node: MappingNode, deep: bool = False) -> dict[Any, Any]:
            seen: set[Any] = set()
            for key_node, _ in node.value:
                if isinstance(key_node, ScalarNode) and key_node.tag != "tag:yaml.org,2002:merge":
                    key = self.construct_object(key_node, deep=deep)
                    try:
                        fresh = key not in seen
                        seen.add(key)
                    except TypeError:
                        continue
                    if not fresh:
                        mark = key_node.start_mark
                        raise _Refused(
                            f"duplicate key {quote(key)} at line {mark.line + 1}; each key may "
                            "appear once (the second would silently replace the first)"
                        )
            return super().construct_mapping(node, deep=deep)

    # the float resolver of YAML 1.1 replaced by 1.2's (copies: SafeLoader's own lists stay)
    _StrictLoader.yaml_implicit_resolvers = {
        key: [(tag, rx) for tag, rx in value if tag != "tag:yaml.org,2002:float"]
        for key, value in yaml.SafeLoader.yaml_implicit_resolvers.items()
    }
    _StrictLoader.add_implicit_resolver("tag:yaml.org,2002:float", float_12, list("-+0123456789."))
    return _StrictLoader


def _bounded_yaml_error(exc: yaml.YAMLError) -> str:
    # PyYAML's messages quote the offending line with a caret: keep the first line and position
    text = str(exc).strip().splitlines()
    problem = getattr(exc, "problem", None)
    mark = getattr(exc, "problem_mark", None)
    if problem and mark is not None:
        return f"{problem} at line {mark.line + 1}, column {mark.column + 1}"
    return quote(text[0] if text else type(exc).__name__, 200).strip("'\"")


def cache_dir(kind: str) -> Path | None:
    """``$HLTL_CACHE_DIR/<kind>``, else ``$XDG_CACHE_HOME/hltl/<kind>`` or
    ``~/.cache/hltl/<kind>``; ``None`` when ``HLTL_CACHE_DIR`` is ``off`` (or empty or 0)."""
    root = os.environ.get("HLTL_CACHE_DIR")
    if root is not None:
        return None if root in ("", "off", "0") else Path(root) / kind
    xdg = os.environ.get("XDG_CACHE_HOME")
    base = Path(xdg) if xdg else Path.home() / ".cache"
    return base / "hltl" / kind
