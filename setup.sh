#!/usr/bin/env bash
# One-shot set-up for a fresh machine: system packages, .venv/, hltl with its test dependencies.
set -euo pipefail
cd "$(dirname "$0")"

if ! command -v mona >/dev/null 2>&1; then
  echo "setup: installing MONA (Debian package 'mona')" >&2
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq mona >/dev/null
fi

if [ ! -x .venv/bin/python ]; then
  python3 -m venv .venv
fi
.venv/bin/python -m pip install -q --disable-pip-version-check --upgrade pip >/dev/null
.venv/bin/python -m pip install -q --disable-pip-version-check -e '.[test,viz,llm]'
echo "setup: ready (.venv/bin/hltl)" >&2
