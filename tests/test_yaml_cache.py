"""YAML files read before come back from their JSON copy: the same data, or PyYAML decides."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from hltl import fileio
from hltl.errors import SceneError
from hltl.fileio import load_data, load_file

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@pytest.fixture
def cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("HLTL_CACHE_DIR", str(tmp_path / "cache"))
    return tmp_path / "cache" / "yaml"


def _no_yaml(*args: Any, **kwargs: Any) -> Any:
    raise AssertionError("PyYAML was asked")


def _same(a: Any, b: Any) -> bool:
    # equal, and with the same types all the way down (1 == 1.0 == True)
    return a == b and repr(a) == repr(b)


@pytest.mark.parametrize("path", sorted(EXAMPLES.rglob("*.yaml")), ids=lambda p: p.name)
def test_every_example_comes_back_from_the_cache_unchanged(
    path: Path, cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    fresh = load_data(path.read_text(encoding="utf-8"), str(path), SceneError, as_json=False)
    assert _same(load_file(path, "file", SceneError), fresh)
    assert len(list(cache.glob("*.json"))) == 1
    monkeypatch.setattr(fileio, "load_data", _no_yaml)
    assert _same(load_file(path, "file", SceneError), fresh)


@pytest.mark.parametrize(
    ("text", "kept"),
    [
        ("a: [1, 2.0, -0.0, 1e3, .inf, true, null, 'x']\nb: {c: yes}\n", True),
        ("a: &x [1, 2]\nb: *x\n", False),  # an alias: the two lists are one object
        ("when: 2024-01-02\n", False),  # a date
        ("1: one\n", False),  # a key that is no string
        ("!!binary aGk=\n", False),
        ("!!set {a, b}\n", False),
    ],
)
def test_only_data_json_gives_back_unchanged_is_kept(
    text: str, kept: bool, cache: Path, tmp_path: Path
) -> None:
    path = tmp_path / "f.yaml"
    path.write_text(text, encoding="utf-8")
    fresh = load_data(text, str(path), SceneError, as_json=False)
    assert _same(load_file(path, "file", SceneError), fresh)
    assert _same(load_file(path, "file", SceneError), fresh)
    assert len(list(cache.glob("*.json"))) == (1 if kept else 0)


def test_a_refused_file_is_refused_again_and_not_kept(cache: Path, tmp_path: Path) -> None:
    path = tmp_path / "dup.yaml"
    path.write_text("a: 1\na: 2\n", encoding="utf-8")
    for _ in range(2):
        with pytest.raises(SceneError, match="duplicate key 'a' at line 2"):
            load_file(path, "file", SceneError)
    assert not cache.exists() or list(cache.iterdir()) == []


def test_a_damaged_copy_is_read_again_and_replaced(cache: Path, tmp_path: Path) -> None:
    path = tmp_path / "f.yaml"
    path.write_text("a: [1, 2]\n", encoding="utf-8")
    assert load_file(path, "file", SceneError) == {"a": [1, 2]}
    (copy,) = cache.glob("*.json")
    copy.write_text('{"a": [1, 2', encoding="utf-8")
    assert load_file(path, "file", SceneError) == {"a": [1, 2]}
    assert copy.read_text(encoding="utf-8") == '{"a": [1, 2]}'


def test_an_edited_file_is_read_afresh(cache: Path, tmp_path: Path) -> None:
    path = tmp_path / "f.yaml"
    path.write_text("a: 1\n", encoding="utf-8")
    assert load_file(path, "file", SceneError) == {"a": 1}
    path.write_text("a: 2\n", encoding="utf-8")
    assert load_file(path, "file", SceneError) == {"a": 2}


def test_with_the_cache_off_nothing_is_kept(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("HLTL_CACHE_DIR", "off")
    monkeypatch.setenv("HOME", str(tmp_path))
    monkeypatch.delenv("XDG_CACHE_HOME", raising=False)
    path = tmp_path / "f.yaml"
    path.write_text("a: 1\n", encoding="utf-8")
    assert load_file(path, "file", SceneError) == {"a": 1}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["f.yaml"]


def test_a_cached_scene_and_spec_are_read_without_importing_yaml(tmp_path: Path) -> None:
    code = (
        "import sys\n"
        "from hltl.spec.hierarchy import load_spec\n"
        "from hltl.world.scene import load_scene\n"
        f"load_scene({str(EXAMPLES / 'scenes' / 'two_arms.yaml')!r})\n"
        f"load_spec({str(EXAMPLES / 'specs' / 'fig1.yaml')!r})\n"
        "print('yaml' in sys.modules)\n"
    )
    env = {**os.environ, "HLTL_CACHE_DIR": str(tmp_path)}
    runs = [
        subprocess.run(
            [sys.executable, "-c", code], capture_output=True, text=True, check=True, env=env
        ).stdout.strip()
        for _ in range(2)
    ]
    assert runs == ["True", "False"]


@pytest.mark.parametrize("size", [0, 1, 55, 56, 64, 1000, 70_000])
def test_the_cache_keys_are_hashlib_sha256_digests(size: int) -> None:
    # fileio.sha256 (CPython's own SHA-256, no OpenSSL to load) keys the YAML and DFA caches:
    # the digests hashlib gives, so files kept before stay found
    import hashlib

    data = bytes(range(256)) * (size // 256) + bytes(range(size % 256))
    assert fileio.sha256(data).hexdigest() == hashlib.sha256(data).hexdigest()
    mine, theirs = fileio.sha256(data), hashlib.sha256(data)
    mine.update(b"\nmore")
    theirs.update(b"\nmore")
    assert mine.hexdigest() == theirs.hexdigest()
