"""Teaches one fish to push the ball into the goal in polo-1v1 against idle, by PPO on FishVecEnv.

    bash clients/python/build-native.sh && dotnet build src/URWPGSim2D.Server
    PYTHONPATH=clients/python python3 -m urwpgsim2d.examples.train_polo --minutes 12 --out out/learning

PPO (clipped objective, generalised advantage estimation, a value network, Adam) with PyTorch
where it can be imported, in numpy alone otherwise (--backend). An episode is the first half of a
match (polo-1v1, 6,000 cycles, so 3,000 cycles with team 0 attacking the right-hand goal); the
matches play on across iterations, 64 at once. The policy decides every REPEAT cycles among
ACTIONS (3 speed codes times 5 turn codes) from FEATURES: the ball and the push line seen from the
fish, the fish and the ball on the field, the keeper of the other team, the last action. Reward:
GOAL_REWARD per goal (the environment's reward) plus shaping, the change of a potential: the fish
near a point behind the ball on the line to the goal, the ball near the goal.

At the end it evaluates the trained policy and a random one (uniform over ACTIONS) on the same
seeded episodes and prints the share of episodes with a goal, writes the learning curve (curve.png:
matplotlib when it can be imported, else a small PNG writer of its own; and curve.svg) and plays a
match of the trained fish through the server (FishEnv) to its end, so the server writes its replay
page (replay.html).
"""

import argparse
import math
import os
import struct
import sys
import time
import zlib

import numpy as np

from urwpgsim2d.vec import FishVecEnv

ITEM, OPPONENT, CYCLES = "polo-1v1", "idle", 6000
HALF = CYCLES // 2  # an episode: the first half, team 0 attacking the right-hand goal
REPEAT = 4  # cycles per decision
SPEEDS = (2, 6, 10)
TURNS = (0, 3, 7, 11, 14)
ACTIONS = np.array([(v, t) for v in SPEEDS for t in TURNS], dtype=np.int32)
STRAIGHT = 2  # index of (2, 7): slow and straight, the "last action" at kick-off
GOAL_X = 1.5  # m: the end line of the goal attacked
GOAL_REWARD = 10.0
W_FISH, W_BALL, BEHIND = 1.0, 3.0, 0.2


def features(obs: np.ndarray, last: np.ndarray, side: float = 1.0) -> np.ndarray:
    """What the policy sees (obs: rows of polo-1v1's observation; last: the last action's index; side -1 mirrors the field when attacking left)."""
    x, y, c, s = (obs[:, k] * side for k in range(4))
    kx, ky = obs[:, 5] * side, obs[:, 6] * side  # the other team's fish
    bx, by = obs[:, 10] * side, obs[:, 11] * side
    dx, dy = bx - x, by - y
    d = np.hypot(dx, dy)
    gx, gy = GOAL_X - bx, -by
    g = np.maximum(np.hypot(gx, gy), 1e-6)
    ux, uy = gx / g, gy / g  # the push line: from the ball to the goal

    def own(vx, vy):  # a vector in the fish's frame: ahead, and across (> 0 on the side turn codes above 7 turn to)
        return vx * c + vy * s, -vx * s + vy * c

    rx, ry = own(dx, dy)
    lx, ly = own(ux, uy)
    kx_, ky_ = own(kx - x, ky - y)
    onehot = np.zeros((len(obs), len(ACTIONS)))
    onehot[np.arange(len(obs)), last] = 1
    columns = [rx, ry, d, rx / np.maximum(d, 0.05), ry / np.maximum(d, 0.05), lx, ly,
               -(dx * ux + dy * uy), dx * uy - dy * ux, g, x / 1.5, y, c, s, bx / 1.5, by,
               obs[:, 4] / 0.3, np.clip(kx_, -1, 1), np.clip(ky_, -1, 1)]
    return np.concatenate([np.stack(columns, axis=1), onehot], axis=1)


def potential(obs: np.ndarray) -> np.ndarray:
    """Higher when the fish is behind the ball on its line to the goal and the ball near the goal."""
    x, y, bx, by = obs[:, 0], obs[:, 1], obs[:, 10], obs[:, 11]
    gx, gy = GOAL_X - bx, -by
    g = np.maximum(np.hypot(gx, gy), 1e-6)
    return -W_FISH * np.hypot(bx - BEHIND * gx / g - x, by - BEHIND * gy / g - y) - W_BALL * g


FEATURES = features(np.zeros((1, 15), dtype=np.float32), np.zeros(1, dtype=int)).shape[1]


# -- the networks: numpy, or PyTorch ------------------------------------------------------------------


class NumpyMLP:
    """A tanh MLP with hand-written gradients and its own Adam."""

    def __init__(self, sizes, rng, last_scale):
        self.p = {}
        for i in range(len(sizes) - 1):
            scale = (last_scale if i == len(sizes) - 2 else math.sqrt(2)) / math.sqrt(sizes[i])
            self.p["w%d" % i] = rng.normal(0, scale, (sizes[i], sizes[i + 1]))
            self.p["b%d" % i] = np.zeros(sizes[i + 1])
        self.layers = len(sizes) - 1
        self.m = {k: np.zeros_like(v) for k, v in self.p.items()}
        self.v = {k: np.zeros_like(v) for k, v in self.p.items()}
        self.t = 0

    def forward(self, x):
        hs = [x]
        for i in range(self.layers):
            z = hs[-1] @ self.p["w%d" % i] + self.p["b%d" % i]
            hs.append(np.tanh(z) if i < self.layers - 1 else z)
        return hs[-1], hs

    def gradients(self, hs, g_out):
        """The gradient of a loss by every parameter, from its gradient by the output (back-propagation)."""
        grads, g = {}, g_out
        for i in reversed(range(self.layers)):
            grads["w%d" % i] = hs[i].T @ g
            grads["b%d" % i] = g.sum(axis=0)
            if i > 0:
                g = (g @ self.p["w%d" % i].T) * (1 - hs[i] ** 2)
        return grads

    def step(self, grads, lr, max_norm=0.5):
        """One Adam step down `grads` (scaled to a norm of at most max_norm)."""
        k = min(1.0, max_norm / (math.sqrt(sum(float((v ** 2).sum()) for v in grads.values())) + 1e-8))
        self.t += 1
        for name, g in grads.items():
            self.m[name] = 0.9 * self.m[name] + 0.1 * k * g
            self.v[name] = 0.999 * self.v[name] + 0.001 * (k * g) ** 2
            self.p[name] -= lr * (self.m[name] / (1 - 0.9 ** self.t)) / (np.sqrt(self.v[name] / (1 - 0.999 ** self.t)) + 1e-8)


def softmax(z):
    z = z - z.max(axis=1, keepdims=True)
    e = np.exp(z)
    return e / e.sum(axis=1, keepdims=True)


class NumpyAgent:
    """Policy and value networks (64-64 tanh) in numpy, and PPO's update."""

    name = "numpy"

    def __init__(self, seed: int, lr: float):
        rng = np.random.default_rng(seed)
        self.pi = NumpyMLP([FEATURES, 64, 64, len(ACTIONS)], rng, 0.01)
        self.vf = NumpyMLP([FEATURES, 64, 64, 1], rng, 1.0)
        self.lr = lr

    def probabilities(self, f):
        return softmax(self.pi.forward(f)[0])

    def value(self, f):
        return self.vf.forward(f)[0][:, 0]

    def policy_gradients(self, f, a, old_logp, adv, clip, entropy):
        """The gradient of PPO's policy loss -mean(min(r A, clip(r) A)) - entropy * mean(H) by the policy's parameters."""
        logits, hs = self.pi.forward(f)
        p = softmax(logits)
        m = len(a)
        ratio = np.exp(np.log(p[np.arange(m), a] + 1e-12) - old_logp)
        live = ~(((adv > 0) & (ratio > 1 + clip)) | ((adv < 0) & (ratio < 1 - clip)))
        onehot = np.zeros_like(p)
        onehot[np.arange(m), a] = 1
        logp = np.log(p + 1e-12)
        h = -(p * logp).sum(axis=1, keepdims=True)
        # By the logits: d(-r A)/dz = -r A (onehot - p) where not clipped; d(-H)/dz = p (log p + H).
        return self.pi.gradients(hs, (-(live * ratio * adv)[:, None] * (onehot - p) + entropy * p * (logp + h)) / m)

    def value_gradients(self, f, ret):
        """The gradient of the value loss mean((v - ret)^2) / 2 by the value network's parameters."""
        v, hv = self.vf.forward(f)
        return self.vf.gradients(hv, (v[:, 0] - ret)[:, None] / len(ret))

    def update(self, f, a, old_logp, adv, ret, clip, entropy):
        self.pi.step(self.policy_gradients(f, a, old_logp, adv, clip, entropy), self.lr)
        self.vf.step(self.value_gradients(f, ret), self.lr)

    def state(self):
        return {k: v.copy() for k, v in self.pi.p.items()}


class TorchAgent:
    """The same networks and update in PyTorch."""

    name = "torch"

    def __init__(self, seed: int, lr: float):
        import torch

        self.torch = torch
        torch.manual_seed(seed)
        nn = torch.nn

        def mlp(out, scale):
            net = nn.Sequential(nn.Linear(FEATURES, 64), nn.Tanh(), nn.Linear(64, 64), nn.Tanh(), nn.Linear(64, out))
            for layer in net:
                if isinstance(layer, nn.Linear):
                    nn.init.orthogonal_(layer.weight, scale if layer.out_features == out else math.sqrt(2))
                    nn.init.zeros_(layer.bias)
            return net.double()

        self.pi, self.vf = mlp(len(ACTIONS), 0.01), mlp(1, 1.0)
        self.optimiser = torch.optim.Adam(list(self.pi.parameters()) + list(self.vf.parameters()), lr=lr, eps=1e-8)

    def probabilities(self, f):
        with self.torch.no_grad():
            return self.torch.softmax(self.pi(self.torch.from_numpy(f)), dim=1).numpy()

    def value(self, f):
        with self.torch.no_grad():
            return self.vf(self.torch.from_numpy(f))[:, 0].numpy()

    def update(self, f, a, old_logp, adv, ret, clip, entropy):
        torch = self.torch
        f, a = torch.from_numpy(f), torch.from_numpy(a)
        old_logp, adv, ret = torch.from_numpy(old_logp), torch.from_numpy(adv), torch.from_numpy(ret)
        logp_all = torch.log_softmax(self.pi(f), dim=1)
        ratio = torch.exp(logp_all.gather(1, a[:, None])[:, 0] - old_logp)
        policy_loss = -torch.min(ratio * adv, torch.clamp(ratio, 1 - clip, 1 + clip) * adv).mean()
        h = -(logp_all.exp() * logp_all).sum(dim=1).mean()
        value_loss = 0.5 * ((self.vf(f)[:, 0] - ret) ** 2).mean()
        self.optimiser.zero_grad()
        (policy_loss - entropy * h + value_loss).backward()
        torch.nn.utils.clip_grad_norm_(self.pi.parameters(), 0.5)
        torch.nn.utils.clip_grad_norm_(self.vf.parameters(), 0.5)
        self.optimiser.step()

    def state(self):
        return {k: v.detach().numpy().copy() for k, v in self.pi.state_dict().items()}


def make_agent(backend: str, seed: int, lr: float):
    """backend "torch", "numpy", or "auto" (torch when it can be imported)."""
    if backend == "auto":
        try:
            import torch  # noqa: F401
            backend = "torch"
        except ImportError:
            backend = "numpy"
    return TorchAgent(seed, lr) if backend == "torch" else NumpyAgent(seed, lr)


# -- training ---------------------------------------------------------------------------------------


def sample(p: np.ndarray, rng) -> np.ndarray:
    return (p.cumsum(axis=1) > rng.random((len(p), 1))).argmax(axis=1)


def train(agent, minutes: float, envs: int = 64, seed: int = 1, iterations=None, episode: int = HALF,
          rollout: int = 64, epochs: int = 4, minibatch: int = 1024,
          gamma: float = 0.99, lam: float = 0.95, clip: float = 0.2, entropy: float = 0.01, log=print):
    """PPO for `minutes` (or `iterations`) on episodes of `episode` cycles.

    Returns the learning curve: (iteration, seconds, mean return, share with a goal) per batch of episodes.
    """
    rng = np.random.default_rng(seed)
    env = FishVecEnv(ITEM, OPPONENT, num_envs=envs, cycles=CYCLES)
    decisions = episode // REPEAT
    curve = []
    start = time.time()

    def begin():
        obs, _ = env.reset(seed=[int(s) for s in rng.integers(0, 2 ** 31, envs)], options={"max_steps": decisions * REPEAT})
        return obs, np.full(envs, STRAIGHT), 0, np.zeros(envs), np.zeros(envs)

    obs, last, decided, returns, goals = begin()
    iteration = 0
    try:
        while (iterations is None and time.time() - start < minutes * 60) or (iterations is not None and iteration < iterations):
            F = np.zeros((rollout, envs, FEATURES))
            A = np.zeros((rollout, envs), dtype=np.int64)
            R, LOGP, V = np.zeros((rollout, envs)), np.zeros((rollout, envs)), np.zeros((rollout + 1, envs))
            ENDS, BOOTSTRAP = np.zeros(rollout, dtype=bool), np.zeros((rollout, envs))
            for t in range(rollout):
                f = features(obs, last)
                p = agent.probabilities(f)
                a = sample(p, rng)
                V[t] = agent.value(f)
                before = potential(obs)
                scored = np.zeros(envs)
                for _ in range(REPEAT):
                    obs, r, _, _, _ = env.step(ACTIONS[a])
                    scored += r
                # No shaping across a goal: the kick-off puts fish and ball back.
                R[t] = GOAL_REWARD * scored + np.where(scored != 0, 0.0, potential(obs) - before)
                F[t], A[t], LOGP[t] = f, a, np.log(p[np.arange(envs), a] + 1e-12)
                returns += R[t]
                goals += scored
                last = a
                decided += 1
                if decided == decisions:  # the half is over: the episode is cut, its value carried on
                    BOOTSTRAP[t], ENDS[t] = agent.value(features(obs, last)), True
                    curve.append((iteration, time.time() - start, float(returns.mean()), float((goals > 0).mean())))
                    log("iteration %4d  %5.0f s  episode return %7.2f  episodes with a goal %3.0f%%"
                        % (iteration, curve[-1][1], curve[-1][2], 100 * curve[-1][3]))
                    obs, last, decided, returns, goals = begin()
            V[rollout] = agent.value(features(obs, last))
            adv, running = np.zeros((rollout, envs)), np.zeros(envs)
            for t in reversed(range(rollout)):
                following = BOOTSTRAP[t] if ENDS[t] else V[t + 1]
                running = R[t] + gamma * following - V[t] + (0.0 if ENDS[t] else gamma * lam) * running
                adv[t] = running
            ret = (adv + V[:rollout]).reshape(-1)
            adv = adv.reshape(-1)
            adv = (adv - adv.mean()) / (adv.std() + 1e-8)
            f, a, old = F.reshape(-1, FEATURES), A.reshape(-1), LOGP.reshape(-1)
            for _ in range(epochs):
                for part in np.array_split(rng.permutation(len(a)), max(1, len(a) // minibatch)):
                    agent.update(f[part], a[part], old[part], adv[part], ret[part], clip, entropy)
            iteration += 1
    finally:
        env.close()
    return curve


def evaluate(agent, episodes: int, seed: int, policy: str = "greedy", episode: int = HALF) -> float:
    """The share of `episodes` episodes (seeds seed, seed + 1, ...) with a goal.

    policy: "greedy" (the trained policy's likeliest action), "sampled" (drawn from it) or "random" (uniform over ACTIONS).
    """
    env = FishVecEnv(ITEM, OPPONENT, num_envs=episodes, cycles=CYCLES)
    rng = np.random.default_rng(seed)
    try:
        obs, _ = env.reset(seed=seed, options={"max_steps": episode // REPEAT * REPEAT})
        last, goals = np.full(episodes, STRAIGHT), np.zeros(episodes)
        for _ in range(episode // REPEAT):
            if policy == "random":
                a = rng.integers(0, len(ACTIONS), episodes)
            else:
                p = agent.probabilities(features(obs, last))
                a = p.argmax(axis=1) if policy == "greedy" else sample(p, rng)
            for _ in range(REPEAT):
                obs, r, _, _, _ = env.step(ACTIONS[a])
                goals += r
            last = a
        return float((goals > 0).mean())
    finally:
        env.close()


# -- the learning curve and the replay page ---------------------------------------------------------------


def write_png(path: str, pixels: np.ndarray) -> None:
    """pixels (height, width, 3) uint8 as an 8-bit RGB PNG (signature, IHDR, one zlib IDAT, IEND)."""
    height, width, _ = pixels.shape
    raw = b"".join(b"\x00" + pixels[row].tobytes() for row in range(height))

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def plot_curve(path: str, curve, use_matplotlib: bool = True) -> str:
    """The mean episode return and the share of episodes with a goal against training time; returns what drew it."""
    seconds = np.array([c[1] for c in curve]) / 60
    returns = np.array([c[2] for c in curve])
    scored = np.array([c[3] for c in curve])
    if use_matplotlib:
        try:
            import matplotlib
            matplotlib.use("Agg")
            import matplotlib.pyplot as plt
        except ImportError:
            use_matplotlib = False
    if use_matplotlib:
        fig, left = plt.subplots(figsize=(7, 4), dpi=100)
        left.plot(seconds, returns, color="tab:blue", marker="o", markersize=3)
        left.set_xlabel("training time (min)")
        left.set_ylabel("episode return (shaped)", color="tab:blue")
        right = left.twinx()
        right.plot(seconds, 100 * scored, color="tab:orange", marker="s", markersize=3)
        right.set_ylabel("episodes with a goal (%)", color="tab:orange")
        right.set_ylim(0, 100)
        left.set_title("PPO, polo-1v1 against idle")
        fig.tight_layout()
        fig.savefig(path)
        plt.close(fig)
        return "matplotlib"
    width, height, margin = 640, 360, 30
    img = np.full((height, width, 3), 255, dtype=np.uint8)
    img[height - margin, margin:width - margin] = img[margin:height - margin, margin] = img[margin:height - margin, width - margin] = 0
    span = max(seconds.max() - seconds.min(), 1e-9) if len(seconds) else 1.0

    def line(values, low, high, colour):
        xs = margin + (seconds - seconds.min()) / span * (width - 2 * margin)
        ys = height - margin - (values - low) / max(high - low, 1e-9) * (height - 2 * margin)
        points = list(zip(xs, ys))
        for (x0, y0), (x1, y1) in zip(points, points[1:] or points):
            for k in np.linspace(0, 1, int(max(abs(x1 - x0), abs(y1 - y0))) + 2):
                x, y = int(round(x0 + k * (x1 - x0))), int(round(y0 + k * (y1 - y0)))
                img[max(y - 1, 0):y + 2, max(x - 1, 0):x + 2] = colour

    if len(curve):
        line(returns, returns.min(), returns.max(), (31, 119, 180))
        line(scored, 0.0, 1.0, (255, 127, 14))
    write_png(path, img)
    return "built-in PNG writer"


def svg_curve(path: str, curve) -> None:
    """The same curve as an SVG drawing (text: return in blue, goal share in orange, 0..100 % on the right)."""
    width, height, left, right, top, bottom = 640, 360, 60, 60, 30, 40
    seconds = [c[1] / 60 for c in curve] or [0.0]
    returns = [c[2] for c in curve] or [0.0]
    scored = [100 * c[3] for c in curve] or [0.0]
    t0, t1 = min(seconds), max(max(seconds), min(seconds) + 1e-9)
    r0, r1 = min(returns), max(max(returns), min(returns) + 1e-9)

    def points(values, low, high):
        return " ".join("%.1f,%.1f" % (left + (t - t0) / (t1 - t0) * (width - left - right),
                                       height - bottom - (v - low) / (high - low) * (height - top - bottom)) for t, v in zip(seconds, values))

    text = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="12">' % (width, height),
            '<rect width="100%" height="100%" fill="white"/>',
            '<path d="M%d %d V%d H%d V%d" fill="none" stroke="black"/>' % (left, top, height - bottom, width - right, top),
            '<polyline points="%s" fill="none" stroke="#1f77b4" stroke-width="2"/>' % points(returns, r0, r1),
            '<polyline points="%s" fill="none" stroke="#ff7f0e" stroke-width="2"/>' % points(scored, 0.0, 100.0),
            '<text x="%d" y="%d" text-anchor="middle">training time: %.1f to %.1f min</text>' % (width / 2, height - 12, t0, t1),
            '<text x="%d" y="%d" fill="#1f77b4">episode return (shaped): %.1f to %.1f</text>' % (left, top - 10, r0, r1),
            '<text x="%d" y="%d" fill="#ff7f0e" text-anchor="end">episodes with a goal: 0 to 100 %%</text>' % (width - right, top - 10),
            '</svg>']
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(text) + "\n")


def replay(agent, path: str, seed: int, cycles: int = 2 * HALF // 3):
    """Plays a match of `cycles` cycles (two halves) of the trained fish through the server to its end, when the server writes the page."""
    from urwpgsim2d.env import FishEnv

    env = FishEnv(item=ITEM, opponent=OPPONENT, cycles=cycles, run_args=["--html", path, "--force"])
    try:
        obs, info = env.reset(seed=seed, options={"to_end": True})
        last, step, a = np.full(1, STRAIGHT), 0, 0
        while True:
            if step % REPEAT == 0:
                side = -1.0 if info["sides_swapped"] else 1.0
                row = np.asarray(obs, dtype=np.float32)[None, :]
                a = int(agent.probabilities(features(row, last, side)).argmax(axis=1)[0])
                last = np.full(1, a)
            obs, _, terminated, _, info = env.step(list(ACTIONS[a]))
            step += 1
            if terminated:
                return info["end"]
    finally:
        env.close()


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--minutes", type=float, default=12.0, help="training time (default 12)")
    parser.add_argument("--iterations", type=int, default=None, help="train this many iterations instead (a quick check)")
    parser.add_argument("--envs", type=int, default=64, help="matches stepped at once (default 64)")
    parser.add_argument("--episodes", type=int, default=32, help="seeded episodes of the evaluation (default 32)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--backend", choices=("auto", "torch", "numpy"), default="auto", help="auto: torch when it can be imported")
    parser.add_argument("--episode-cycles", type=int, default=HALF, help="cycles of an episode (default %d, the first half)" % HALF)
    parser.add_argument("--replay-cycles", type=int, default=2 * HALF // 3, help="cycles of the replayed match (default %d)" % (2 * HALF // 3))
    parser.add_argument("--plot", choices=("auto", "builtin"), default="auto", help="auto: matplotlib when it can be imported")
    parser.add_argument("--out", default="out/learning", help="folder of curve.png and replay.html")
    args = parser.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    started = time.time()
    agent = make_agent(args.backend, args.seed, lr=1e-3)
    print("PPO in %s: %s against %s, %d matches at once" % (agent.name, ITEM, OPPONENT, args.envs))
    curve = train(agent, args.minutes, envs=args.envs, seed=args.seed, iterations=args.iterations, episode=args.episode_cycles)
    rates = {policy: evaluate(agent, args.episodes, seed=10 ** 6, policy=policy, episode=args.episode_cycles)
             for policy in ("greedy", "sampled", "random")}
    print("episodes with a goal (%d seeded episodes of %d cycles): trained %.0f%% (sampled actions %.0f%%), random %.0f%%"
          % (args.episodes, args.episode_cycles, 100 * rates["greedy"], 100 * rates["sampled"], 100 * rates["random"]))
    curve_path = os.path.join(args.out, "curve.png")
    how = plot_curve(curve_path, curve, use_matplotlib=args.plot == "auto")
    svg_curve(os.path.join(args.out, "curve.svg"), curve)
    print("wrote %s (%s) and curve.svg" % (curve_path, how))
    page = os.path.abspath(os.path.join(args.out, "replay.html"))
    end = replay(agent, page, seed=7, cycles=args.replay_cycles)
    print("wrote %s: a match of the trained fish against idle (seed 7), %d cycles, %d:%d" % (page, end["cycle"], end["goals"][0], end["goals"][1]))
    print("%.1f minutes in all" % ((time.time() - started) / 60))
    return 0


if __name__ == "__main__":
    sys.exit(main())
