"""The learned trajectory predictor: a GRU that corrects the goal-directed forecast."""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from hltl.errors import BackendUnavailableError
from hltl.perception.detection import read_weights
from hltl.perception.forecast import DT, F64, T_OBS, T_PRED, fit_velocity, goal_forecast
from hltl.perception.walks import MIX, generate_walks

K_STOPS = 6  # nearest stopping places the model sees
STOP_RANGE = 4.0  # metres; farther places are left out
HIDDEN = 48
WIDTH = 128
SHIPPED = Path(__file__).with_name("data") / "gru_predictor.npz"


# -- features (numpy; shared by training and inference) --------------------------------------


@dataclass(frozen=True, slots=True)
class Features:
    """One window in the person's frame (batch of one or many)."""

    seq: F64  # (B, T_OBS, 4): position and step, metres
    ctx: F64  # (B, K_STOPS * 3): nearest stopping places (x, y, present)
    prior: F64  # (B, T_PRED * 2): goal-directed forecast
    origin: F64  # (B, 2) world position of the frame's origin
    rot: F64  # (B, 2, 2) world-to-frame rotation


def frame_of(obs: F64) -> tuple[F64, F64]:
    v = fit_velocity(obs)
    s = float(np.hypot(*v))
    if s == 0:
        d = obs[-1] - obs[0]
        s_d = float(np.hypot(*d))
        v, s = (d, s_d) if s_d > 0.05 else (np.array([1.0, 0.0]), 1.0)
    c, n = v[0] / s, v[1] / s
    return obs[-1].copy(), np.array([[c, n], [-n, c]])


def features(obs: F64, stops: F64, prior: F64 | None = None) -> Features:
    """The model's input for one observed grid track ``obs`` (T_OBS, 2)."""
    origin, rot = frame_of(obs)
    local = (obs - origin) @ rot.T
    steps = np.diff(local, axis=0, prepend=local[:1])
    seq = np.concatenate([local, steps], axis=1)
    ctx = np.zeros((K_STOPS, 3))
    if len(stops):
        rel = (stops - origin) @ rot.T
        d = np.hypot(rel[:, 0], rel[:, 1])
        order = [i for i in np.argsort(d, kind="stable") if d[i] <= STOP_RANGE][:K_STOPS]
        ctx[: len(order), :2] = rel[order]
        ctx[: len(order), 2] = 1.0
    pr = goal_forecast(obs, stops) if prior is None else prior
    pr_local = (pr - origin) @ rot.T
    return Features(seq[None], ctx.reshape(1, -1), pr_local.reshape(1, -1), origin[None], rot[None])


def stack(items: Sequence[Features]) -> Features:
    return Features(
        np.concatenate([f.seq for f in items]),
        np.concatenate([f.ctx for f in items]),
        np.concatenate([f.prior for f in items]),
        np.concatenate([f.origin for f in items]),
        np.concatenate([f.rot for f in items]),
    )


def to_world(local: F64, f: Features) -> F64:
    """(B, T_PRED*2) frame coordinates → (B, T_PRED, 2) world points."""
    pts = local.reshape(len(local), -1, 2)
    return np.asarray(np.einsum("btj,bjk->btk", pts, f.rot) + f.origin[:, None, :], dtype=float)


# -- the model -------------------------------------------------------------------------------


def _torch() -> Any:
    try:
        import torch
    except ImportError as exc:
        raise BackendUnavailableError(
            "the GRU trajectory predictor needs torch: pip install 'hltl[predict]'"
        ) from exc
    return torch


def _build(torch: Any) -> Any:
    nn = torch.nn

    class Net(nn.Module):  # type: ignore[name-defined,misc]
        def __init__(self) -> None:
            super().__init__()
            self.gru = nn.GRU(4, HIDDEN, batch_first=True)
            self.mlp = nn.Sequential(
                nn.Linear(HIDDEN + K_STOPS * 3 + T_PRED * 2, WIDTH),
                nn.ReLU(),
                nn.Linear(WIDTH, WIDTH),
                nn.ReLU(),
                nn.Linear(WIDTH, T_PRED * 2),
            )
            nn.init.zeros_(self.mlp[-1].weight)
            nn.init.zeros_(self.mlp[-1].bias)

        def forward(self, seq: Any, ctx: Any, prior: Any) -> Any:
            _, h = self.gru(seq)
            return prior + self.mlp(torch.cat([h[-1], ctx, prior], dim=1))

    return Net()


class GRUModel:
    """A loaded GRU predictor (inference only, CPU)."""

    def __init__(self, state: dict[str, F64], meta: dict[str, Any]) -> None:
        torch = _torch()
        # one forecast is a few tiny matrix products: with a thread pool on a loaded 2-core
        # machine it took 24 ms, with one thread 1.2 ms
        torch.set_num_threads(1)
        self._torch = torch
        self.meta = meta
        self.net = _build(torch)
        self.net.load_state_dict({k: torch.from_numpy(np.asarray(v)) for k, v in state.items()})
        self.net.eval()

    def forecast_batch(self, f: Features) -> F64:
        """(B, T_PRED, 2) world forecasts."""
        torch = self._torch
        with torch.no_grad():
            out = self.net(
                torch.from_numpy(f.seq.astype(np.float32)),
                torch.from_numpy(f.ctx.astype(np.float32)),
                torch.from_numpy(f.prior.astype(np.float32)),
            )
        return to_world(out.numpy().astype(float), f)

    def forecast(self, obs: F64, stops: F64) -> F64:
        """(T_PRED, 2) world forecast for one observed grid track."""
        out: F64 = self.forecast_batch(features(obs, stops))[0]
        return out


def load_model(path: str | Path | None = None) -> GRUModel:
    """Load weights written by :func:`train` (default: the shipped file).

    Raises:
        BackendUnavailableError: torch is missing.
        FileNotFoundError / ValueError: the file is missing or not a weights file.
    """
    p = SHIPPED if path is None else Path(path)
    meta, state = read_weights(p, "a GRU predictor weights file")
    if meta.get("t_obs") != T_OBS or meta.get("t_pred") != T_PRED or meta.get("dt") != DT:
        raise ValueError(f"{p}: weights were trained for another grid ({meta})")
    try:
        return GRUModel(state, meta)
    except RuntimeError as exc:  # shape mismatch in load_state_dict
        raise ValueError(f"{p}: weights do not fit this model ({exc})") from exc


# -- training --------------------------------------------------------------------------------


def windows(
    observed: F64, true: F64, stops: F64, stride: int = 2
) -> tuple[list[Features], list[F64]]:
    """Training windows of one walk: features at every ``stride``-th sample with a full future."""
    feats: list[Features] = []
    targets: list[F64] = []
    n = len(true)
    for i in range(1, n - T_PRED, stride):
        lo = i - T_OBS + 1
        idx = np.clip(np.arange(lo, i + 1), 0, None)
        obs = observed[idx]
        fut = true[i + 1 : i + 1 + T_PRED]
        standing = float(np.ptp(np.concatenate([obs, fut]), axis=0).max()) < 0.02
        if standing and (i // stride) % 8:
            continue  # keep one in eight standing windows: they are easy and plentiful
        feats.append(features(obs, stops))
        targets.append(fut)
    return feats, targets


@dataclass(frozen=True, slots=True)
class TrainResult:
    path: Path
    samples: int
    epochs: int
    train_ade: float
    val_ade: float
    val_prior_ade: float
    seconds: float


def train(
    out: str | Path,
    *,
    seed: int = 0,
    walks: int = 600,
    epochs: int = 12,
    mix: Sequence[float] = MIX,
    command: str = "",
    progress: Callable[[str, float], None] | None = None,
) -> TrainResult:
    """Train the GRU on ``walks`` seeded walks (90 % train, 10 % validation) and write weights.

    ``mix`` weighs the leg kinds of :data:`hltl.perception.walks.KINDS` in the training walks.

    The loss is the mean Euclidean error over the 2 s forecast (ADE). ``progress`` is called
    with a phase name and a fraction done.
    """
    torch = _torch()
    t0 = time.perf_counter()
    torch.manual_seed(seed)
    rng = np.random.default_rng(seed)
    all_walks = generate_walks(seed, walks, mix=mix)
    feats: list[Features] = []
    targets: list[F64] = []
    for k, w in enumerate(all_walks):
        f, t = windows(w.observed, w.true, w.stops)
        feats += f
        targets += t
        if progress:
            progress("features", (k + 1) / len(all_walks))
    data = stack(feats)
    # targets in each window's frame
    tgt = np.einsum("btk,bjk->btj", np.stack(targets) - data.origin[:, None, :], data.rot)
    n = len(tgt)
    order = rng.permutation(n)
    n_val = max(1, n // 10)
    val, tr = order[:n_val], order[n_val:]

    def tensors(idx: npt.NDArray[np.int64]) -> tuple[Any, Any, Any, Any]:
        return (
            torch.from_numpy(data.seq[idx].astype(np.float32)),
            torch.from_numpy(data.ctx[idx].astype(np.float32)),
            torch.from_numpy(data.prior[idx].astype(np.float32)),
            torch.from_numpy(tgt[idx].reshape(len(idx), -1).astype(np.float32)),
        )

    train_t, val_t = tensors(tr), tensors(val)
    net = _build(torch)
    opt = torch.optim.Adam(net.parameters(), lr=2e-3)
    sched = torch.optim.lr_scheduler.CosineAnnealingLR(opt, T_max=epochs)

    def ade(pred: Any, target: Any) -> Any:
        d = (pred - target).reshape(len(pred), -1, 2)
        return torch.sqrt((d * d).sum(dim=2) + 1e-9).mean()

    batch = 256
    train_loss = math.nan
    for epoch in range(epochs):
        net.train()
        perm = torch.randperm(len(tr))
        total, count = 0.0, 0
        for s in range(0, len(tr), batch):
            b = perm[s : s + batch]
            loss = ade(net(train_t[0][b], train_t[1][b], train_t[2][b]), train_t[3][b])
            opt.zero_grad()
            loss.backward()
            opt.step()
            total += float(loss.detach()) * len(b)
            count += len(b)
        sched.step()
        train_loss = total / count
        if progress:
            progress("training", (epoch + 1) / epochs)
    net.eval()
    with torch.no_grad():
        val_loss = float(ade(net(*val_t[:3]), val_t[3]))
        prior_loss = float(ade(val_t[2], val_t[3]))
    meta = {
        "command": command,
        "seed": seed,
        "walks": walks,
        "epochs": epochs,
        "mix": [float(m) for m in mix],
        "samples": n,
        "dt": DT,
        "t_obs": T_OBS,
        "t_pred": T_PRED,
        "k_stops": K_STOPS,
        "hidden": HIDDEN,
        "train_ade": round(train_loss, 5),
        "val_ade": round(val_loss, 5),
        "val_goal_ade": round(prior_loss, 5),
        "torch": str(torch.__version__),
    }
    path = Path(out)
    path.parent.mkdir(parents=True, exist_ok=True)
    state = {k: v.detach().numpy().astype(np.float32) for k, v in net.state_dict().items()}
    with path.open("wb") as fh:
        np.savez_compressed(fh, meta=np.array(json.dumps(meta)), **state)
    return TrainResult(path, n, epochs, train_loss, val_loss, prior_loss, time.perf_counter() - t0)
