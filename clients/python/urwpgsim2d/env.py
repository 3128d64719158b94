"""FishEnv: one team of a match as a Gymnasium environment, the server started and driven in lockstep.

The environment starts the server itself (run --strategy TEAM=remote:0 against an opponent SPEC,
as fast as the two sides answer), plays the team it is given, and follows the Gymnasium contract:
reset(seed=..., options=...) -> (obs, info), step(action) -> (obs, reward, terminated, truncated, info),
observation_space, action_space. The same seed and actions give the same episode. It subclasses
gymnasium.Env when gymnasium can be imported, and works without it (its spaces are then small
stand-ins with the same shape, bounds, sample() and contains()).
"""

import math
import os
import random
import re
import secrets
import shlex
import subprocess
from typing import Any, Dict, List, Optional, Sequence, Tuple

from . import protocol
from .protocol import Assignment, ProtocolError, Snapshot, goals_of

try:  # optional
    import gymnasium as _gym
    import numpy as _np
except ImportError:  # pragma: no cover - depends on the machine
    _gym = None
    _np = None

_WAITING = re.compile(r"waiting for a client on (\S+):(\d+)")


class Box:
    """Stand-in for gymnasium.spaces.Box (float vectors within bounds)."""

    def __init__(self, low: float, high: float, shape: Tuple[int, ...], seed: Optional[int] = None):
        self.low, self.high, self.shape = low, high, shape
        self._random = random.Random(seed)

    def seed(self, seed: Optional[int] = None) -> None:
        self._random.seed(seed)

    def sample(self) -> List[float]:
        return [self._random.uniform(self.low, self.high) for _ in range(self.shape[0])]

    def contains(self, x) -> bool:
        return len(x) == self.shape[0] and all(self.low <= float(v) <= self.high for v in x)


class MultiDiscrete:
    """Stand-in for gymnasium.spaces.MultiDiscrete (one integer 0..n-1 per entry)."""

    def __init__(self, nvec: Sequence[int], seed: Optional[int] = None):
        self.nvec = list(nvec)
        self.shape = (len(self.nvec),)
        self._random = random.Random(seed)

    def seed(self, seed: Optional[int] = None) -> None:
        self._random.seed(seed)

    def sample(self) -> List[int]:
        return [self._random.randrange(n) for n in self.nvec]

    def contains(self, x) -> bool:
        return len(x) == len(self.nvec) and all(int(v) == v and 0 <= v < n for v, n in zip(x, self.nvec))


def default_server() -> List[str]:
    """The server command: $URWPGSIM2D_SERVER (a command line), else the built server of this repository (the newer of Release and Debug)."""
    command = os.environ.get("URWPGSIM2D_SERVER")
    if command:
        return shlex.split(command)
    root = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
    built = [os.path.join(root, "src", "URWPGSim2D.Server", "bin", configuration, "net10.0", "URWPGSim2D.Server.dll") for configuration in ("Release", "Debug")]
    built = [dll for dll in built if os.path.exists(dll)]
    if built:
        return ["dotnet", max(built, key=os.path.getmtime)]
    raise FileNotFoundError("the server is not built (dotnet build src/URWPGSim2D.Server) and URWPGSIM2D_SERVER is not set")


_Base = _gym.Env if _gym is not None else object


class FishEnv(_Base):
    """One team of a match: the action is a (vcode, tcode) pair per fish, the reward the change of the score difference.

    Observation (floats, in this order): for every fish x/1000, y/1000 (mm -> m), cos and sin of
    its heading, speed/1000; for every ball x/1000, y/1000, vx/1000, vy/1000; then the match's
    time fraction (cycle / cycles, at most 1). Action: 2 integers 0..15 per fish of the team
    (vcode, tcode), flat. Reward: (own score - other score) now minus the same one step before.
    terminated: the match ended within its cycles (they were played, or the item decided it);
    truncated: `cycles` steps were played and the item plays on (a tie that goes to extra time or
    penalties), or options["max_steps"] was reached. An episode is never longer than `cycles` steps,
    unless reset(options={"to_end": True}): then it plays on past `cycles` until the match ends
    (extra time, penalties), so the server writes what run_args ask for (a replay page).
    """

    metadata = {"render_modes": []}

    def __init__(self, item: str = "polo-1v1", opponent: Optional[str] = "chase-ball", team: int = 0, cycles: int = 600,
                 server: Optional[Sequence[str]] = None, deadline_ms: int = 60000, run_args: Sequence[str] = ()):
        if team not in (0, 1):
            raise ValueError("team must be 0 or 1, got %r" % (team,))
        if cycles < 1:
            raise ValueError("cycles must be at least 1, got %r" % (cycles,))
        self.item, self.opponent, self.team, self.cycles, self.deadline_ms = item, opponent, team, cycles, deadline_ms
        self._run_args = list(run_args)  # more options of `run`, e.g. ["--html", "match.html"] (written when a match ends)
        self._server_command = list(server) if server is not None else default_server()
        self._process: Optional[subprocess.Popen] = None
        self._connection: Optional[protocol.Connection] = None
        self._snapshot: Optional[Snapshot] = None
        self._assignment: Optional[Assignment] = None
        self._steps = 0
        self._max_steps: Optional[int] = None
        self._to_end = False
        self._difference = 0
        self.summary: Optional[str] = None
        # The spaces need the match's sizes: a first episode tells them.
        self._start(seed=0)
        self.observation_space, self.action_space = self._spaces()
        self.close()

    # -- the Gymnasium contract ------------------------------------------------------------

    def reset(self, *, seed: Optional[int] = None, options: Optional[Dict[str, Any]] = None):
        if _gym is not None:
            super().reset(seed=seed)
        self.close()
        options = dict(options or {})
        self._max_steps = options.pop("max_steps", None)
        self._to_end = options.pop("to_end", False)
        if options:
            raise ValueError("unknown options: %s" % ", ".join(sorted(options)))
        if not isinstance(self._to_end, bool):
            raise ValueError("options['to_end']: %r, expected True or False" % (self._to_end,))
        self._start(seed=seed if seed is not None else random.randrange(2 ** 31))
        return self._observation(), self._info()

    def step(self, action):
        if self._snapshot is None or self._connection is None:
            raise RuntimeError("step() before reset(), or after the episode ended")
        pairs = self._pairs(action)
        self._connection.send(protocol.decisions(self._snapshot.cycle, pairs))
        self._steps += 1
        message = self._connection.receive()
        if message is None:
            raise ProtocolError("the server closed the connection: %s" % self._server_error())
        if message["type"] == "end":
            goals = goals_of(message)
            reward = float(self._score(goals) - self._difference)
            self._difference = self._score(goals)
            info = self._info()
            info["end"] = {"cycle": int(message["cycle"]), "goals": goals, "faults": int(message["faults"])}
            self._finish()
            return self._last_observation, reward, True, False, info
        if message["type"] != "cycle":
            raise ProtocolError("expected a cycle, got %r" % message["type"])
        self._snapshot = Snapshot.from_json(message, self._assignment)
        difference = self._score(self._snapshot.goals)
        reward = float(difference - self._difference)
        self._difference = difference
        # The match's own length is the episode's: an item that plays on past it (extra time) is cut there.
        truncated = (self._steps >= self.cycles and not self._to_end) or (self._max_steps is not None and self._steps >= self._max_steps)
        observation, info = self._observation(), self._info()
        if truncated:
            self.close()
        return observation, reward, False, truncated, info

    def close(self):
        if self._connection is not None:
            self._connection.close()
            self._connection = None
        if self._process is not None:
            if self._process.poll() is None:
                self._process.kill()
            self._process.wait()
            for stream in (self._process.stdout, self._process.stderr):
                if stream is not None:
                    stream.close()
            self._process = None
        self._snapshot = None

    # -- the server ------------------------------------------------------------------------

    def _start(self, seed: int) -> None:
        token = secrets.token_hex(16)
        command = self._server_command + [
            "run", "--item", self.item, "--cycles", str(self.cycles), "--seed", str(seed),
            "--strategy", "%d=remote:0" % self.team, "--remote-token", token,
            "--strategy-timeout", str(self.deadline_ms), "--remote-wait", "60"]
        if self.opponent is not None:
            command += ["--strategy", "%d=%s" % (1 - self.team, self.opponent)]
        command += self._run_args
        self._process = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        host, port = self._wait_for_port()
        self._connection = protocol.Connection(host, port, timeout=30)
        self._connection.send(protocol.hello(token, "FishEnv"))
        first = self._connection.receive()
        if first is None or first["type"] != "assignment":
            raise ProtocolError("the server did not assign the team: %s" % (first or self._server_error()))
        self._assignment = Assignment.from_json(first)
        cycle = self._connection.receive()
        if cycle is None or cycle["type"] != "cycle":
            raise ProtocolError("the server sent no first cycle: %s" % self._server_error())
        self._snapshot = Snapshot.from_json(cycle, self._assignment)
        self._steps = 0
        self._difference = self._score(self._snapshot.goals)

    def _wait_for_port(self) -> Tuple[str, int]:
        assert self._process is not None and self._process.stderr is not None
        seen = []
        for raw in self._process.stderr:
            line = raw.decode("utf-8", "replace")
            seen.append(line.strip())
            m = _WAITING.search(line)
            if m:
                return m.group(1).strip("[]"), int(m.group(2))
        raise RuntimeError("the server did not start: %s" % " | ".join(seen[-3:]))

    def _finish(self) -> None:
        assert self._process is not None
        out, _ = self._process.communicate(timeout=60)
        self.summary = out.decode("utf-8", "replace")
        self._connection.close()
        self._connection = None
        self._process.stderr.close()
        self._process.stdout.close()
        self._process = None
        self._snapshot = None

    def _server_error(self) -> str:
        if self._process is None:
            return "no server"
        try:
            self._process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            return "the server is still running"
        return self._process.stderr.read().decode("utf-8", "replace").strip()[-500:]

    # -- observations ------------------------------------------------------------------------

    def _score(self, goals: Tuple[int, ...]) -> int:
        return goals[self.team] - goals[1 - self.team]

    def _pairs(self, action) -> List[Tuple[int, int]]:
        values = [int(v) for v in list(action)]
        n = len(self._assignment.fish)
        if len(values) != 2 * n or any(v < 0 or v > 15 for v in values):
            raise ValueError("action must be %d integers 0..15 (vcode, tcode per fish), got %r" % (2 * n, list(action)))
        return [(values[2 * i], values[2 * i + 1]) for i in range(n)]

    def _observation(self):
        s = self._snapshot
        values: List[float] = []
        for f in s.fish:
            values += [f.position[0] / 1000, f.position[1] / 1000, math.cos(f.heading), math.sin(f.heading), f.speed / 1000]
        for b in s.balls:
            values += [b.position[0] / 1000, b.position[1] / 1000, b.velocity[0] / 1000, b.velocity[1] / 1000]
        values.append(min(s.cycle / max(self.cycles, 1), 1.0))
        self._last_observation = _np.asarray(values, dtype=_np.float32) if _np is not None else values
        return self._last_observation

    def _info(self) -> Dict[str, Any]:
        s = self._snapshot
        return {"cycle": s.cycle, "goals": s.goals, "variables": dict(s.variables), "sides_swapped": s.sides_swapped}

    def _spaces(self):
        a = self._assignment
        size = 5 * a.fish_count + 4 * a.ball_count + 1
        nvec = [16] * (2 * len(a.fish))
        if _gym is not None:
            return _gym.spaces.Box(-1e4, 1e4, shape=(size,), dtype=_np.float32), _gym.spaces.MultiDiscrete(nvec)
        return Box(-1e4, 1e4, (size,)), MultiDiscrete(nvec)
