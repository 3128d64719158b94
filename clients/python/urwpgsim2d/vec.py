"""FishVecEnv: many matches stepped at once in this process, through the native library of the match engine.

FishVecEnv(item, opponent, num_envs, team=0, cycles=600) plays num_envs matches of an item in the
native library (liburwpgsim2d.so, built by `bash clients/python/build-native.sh`; found in this
package's native/ folder, or where $URWPGSIM2D_NATIVE points), through ctypes and numpy. It follows
Gymnasium's vector contract: reset(seed=, options=) -> (obs, infos), step(actions) -> (obs, rewards,
terminations, truncations, infos), with next-step autoreset; it subclasses gymnasium.vector.VectorEnv
when gymnasium can be imported, and works without it.

FishParallelEnv(item, opponent, team=0, cycles=600) is one match of the same engine in multi-agent
form, after PettingZoo's ParallelEnv conventions: one agent per fish of the team ("fish_0", ...),
dicts of observations, actions, rewards and flags keyed by agent; it subclasses
pettingzoo.ParallelEnv when pettingzoo can be imported.

Observation, action and reward of one match are FishEnv's (see urwpgsim2d.env.FishEnv): the same
seed and actions give the same episode, except that a match's last observation is its true final
state (FishEnv repeats the one before).
"""

import ctypes
import os
import random
from typing import Any, Dict, Optional, Sequence

import numpy as np

try:  # optional
    import gymnasium as _gym
    from gymnasium.vector.utils import batch_space as _batch_space
except ImportError:  # pragma: no cover - depends on the machine
    _gym = None

try:  # optional
    from pettingzoo import ParallelEnv as _ParallelEnv
except ImportError:  # pragma: no cover - depends on the machine
    _ParallelEnv = object

OPPONENTS = ("idle", "chase-ball", "demo")
"""What the other team can play: the built-in strategies and the item's demo strategy."""


class NativeError(RuntimeError):
    """The native library failed in a way that is not the caller's argument (a bug: report it with the message)."""


def library_path() -> str:
    """The native library: $URWPGSIM2D_NATIVE, else native/liburwpgsim2d.so in this package (bash clients/python/build-native.sh)."""
    path = os.environ.get("URWPGSIM2D_NATIVE")
    if path:
        if not os.path.isfile(path):
            raise FileNotFoundError("URWPGSIM2D_NATIVE=%s: no such file" % path)
        return path
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "native", "liburwpgsim2d.so")
    if not os.path.isfile(path):
        raise FileNotFoundError("the native library is not built: run `bash clients/python/build-native.sh`, or set URWPGSIM2D_NATIVE to liburwpgsim2d.so")
    return path


_lib = None


def _library():
    global _lib
    if _lib is None:
        lib = ctypes.CDLL(library_path())
        p, i32, i64 = ctypes.c_void_p, ctypes.c_int32, ctypes.c_int64
        lib.urw_last_error.restype = ctypes.c_char_p
        lib.urw_last_error.argtypes = []
        lib.urw_batch_create.argtypes = [ctypes.c_char_p, ctypes.c_char_p, i32, i32, i32, ctypes.POINTER(p)]
        lib.urw_batch_destroy.argtypes = [p]
        lib.urw_batch_destroy.restype = None
        lib.urw_batch_sizes.argtypes = [p, p, p, p, p]
        lib.urw_batch_reset.argtypes = [p, p, i64, i32, p, i64]
        lib.urw_batch_step.argtypes = [p, p, i64, p, i64, p, p, p, i64]
        lib.urw_batch_info.argtypes = [p, p, p, p, i64]
        for f in (lib.urw_batch_create, lib.urw_batch_sizes, lib.urw_batch_reset, lib.urw_batch_step, lib.urw_batch_info):
            f.restype = ctypes.c_int
        _lib = lib
    return _lib


def _check(code: int) -> None:
    if code == 0:
        return
    message = _lib.urw_last_error().decode("utf-8", "replace")
    if code == 1:
        raise ValueError(message)
    if code in (2, 3):
        raise RuntimeError(message)
    raise NativeError(message)


class _Box:
    """Stand-in for gymnasium.spaces.Box (float32 arrays within bounds)."""

    def __init__(self, low: float, high: float, shape, seed: Optional[int] = None):
        self.low, self.high, self.shape, self.dtype = low, high, tuple(shape), np.dtype(np.float32)
        self._random = np.random.default_rng(seed)

    def seed(self, seed: Optional[int] = None) -> None:
        self._random = np.random.default_rng(seed)

    def sample(self):
        return self._random.uniform(self.low, self.high, self.shape).astype(np.float32)

    def contains(self, x) -> bool:
        x = np.asarray(x)
        return x.shape == self.shape and bool(np.all((x >= self.low) & (x <= self.high)))


class _MultiDiscrete:
    """Stand-in for gymnasium.spaces.MultiDiscrete (integers 0..n-1 per entry, any shape)."""

    def __init__(self, nvec, seed: Optional[int] = None):
        self.nvec = np.asarray(nvec, dtype=np.int64)
        self.shape, self.dtype = self.nvec.shape, np.dtype(np.int64)
        self._random = np.random.default_rng(seed)

    def seed(self, seed: Optional[int] = None) -> None:
        self._random = np.random.default_rng(seed)

    def sample(self):
        return self._random.integers(0, self.nvec)

    def contains(self, x) -> bool:
        x = np.asarray(x)
        return x.shape == self.shape and bool(np.all((x >= 0) & (x < self.nvec) & (x == np.floor(x))))


_Base = _gym.vector.VectorEnv if _gym is not None else object


class FishVecEnv(_Base):
    """num_envs matches of `item`, team `team` playing the actions, the other team `opponent` ("idle", "chase-ball", "demo").

    Observation (num_envs, obs_size) float32, one row per match, FishEnv's: for every fish x/1000,
    y/1000 (m), cos and sin of its heading, speed/1000; for every ball x/1000, y/1000, vx/1000,
    vy/1000; then the time fraction min(cycle / cycles, 1). Action (num_envs, 2 * fish of the team)
    integers 0..15 (speed code, turn code per fish). Reward: the change of own score minus the
    other team's. terminations: the match ended; truncations: `cycles` steps (or options["max_steps"])
    were played and the match plays on. The step after an episode ended starts that match again
    (next-step autoreset): its action is ignored, its reward is 0, and both flags are False.
    infos: "cycle" (cycles played in the episode), "goals" (team 0's and team 1's score), "seed"
    (the episode's seed: `run --item ITEM --seed SEED` replays it).
    """

    metadata = {"render_modes": [], "autoreset_mode": "next_step"}

    def __init__(self, item: str = "polo-1v1", opponent: str = "chase-ball", num_envs: int = 1, team: int = 0, cycles: int = 600):
        if not isinstance(item, str):
            raise TypeError("item must be a string, got %r" % (item,))
        if not isinstance(opponent, str):
            raise TypeError("opponent must be a string, got %r" % (opponent,))
        for name, value in (("num_envs", num_envs), ("team", team), ("cycles", cycles)):
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
                raise TypeError("%s must be an integer, got %r" % (name, value))
        lib = _library()
        self._lib = lib
        self._handle = ctypes.c_void_p()
        _check(lib.urw_batch_create(item.encode("utf-8"), opponent.encode("utf-8"), int(num_envs), int(team), int(cycles), ctypes.byref(self._handle)))
        sizes = np.zeros(4, dtype=np.int32)
        _check(lib.urw_batch_sizes(self._handle, sizes[0:].ctypes.data, sizes[1:].ctypes.data, sizes[2:].ctypes.data, sizes[3:].ctypes.data))
        self.item, self.opponent, self.team, self.cycles = item, opponent, int(team), int(cycles)
        self.num_envs = int(sizes[0])
        self.observation_size, self.action_size = int(sizes[1]), int(sizes[2])
        n = self.num_envs
        self._obs = np.zeros((n, self.observation_size), dtype=np.float32)
        self._actions = np.zeros((n, self.action_size), dtype=np.int32)
        self._rewards = np.zeros(n, dtype=np.float32)
        self._terminated = np.zeros(n, dtype=np.bool_)
        self._truncated = np.zeros(n, dtype=np.bool_)
        self._cycles = np.zeros(n, dtype=np.int32)
        self._goals = np.zeros((n, 2), dtype=np.int32)
        self._seeds = np.zeros(n, dtype=np.uint64)
        self._step_args = (self._handle, self._actions.ctypes.data, self._actions.size, self._obs.ctypes.data, self._obs.size,
                           self._rewards.ctypes.data, self._terminated.ctypes.data, self._truncated.ctypes.data, n)
        self._started = False
        if _gym is not None:
            self.single_observation_space = _gym.spaces.Box(-1e4, 1e4, shape=(self.observation_size,), dtype=np.float32)
            self.single_action_space = _gym.spaces.MultiDiscrete([16] * self.action_size)
            self.observation_space = _batch_space(self.single_observation_space, n)
            self.action_space = _batch_space(self.single_action_space, n)
        else:
            self.single_observation_space = _Box(-1e4, 1e4, (self.observation_size,))
            self.single_action_space = _MultiDiscrete([16] * self.action_size)
            self.observation_space = _Box(-1e4, 1e4, (n, self.observation_size))
            self.action_space = _MultiDiscrete(np.full((n, self.action_size), 16))

    # -- the Gymnasium vector contract ----------------------------------------------------------

    def reset(self, *, seed=None, options: Optional[Dict[str, Any]] = None):
        """Starts every match: seed an int (match i gets seed + i), a sequence of num_envs ints, or None (random); options {"max_steps": n}."""
        options = dict(options or {})
        max_steps = options.pop("max_steps", None)
        if options:
            raise ValueError("options: unknown %s (known: max_steps)" % ", ".join(sorted(options)))
        if max_steps is None:
            max_steps = 0
        elif isinstance(max_steps, bool) or not isinstance(max_steps, (int, np.integer)) or max_steps < 1:
            raise ValueError("options['max_steps']: %r, expected an integer of 1 or more" % (max_steps,))
        if seed is None:
            seeds = [random.randrange(2 ** 31) for _ in range(self.num_envs)]
        elif isinstance(seed, (int, np.integer)) and not isinstance(seed, bool):
            seeds = [int(seed) + i for i in range(self.num_envs)]
        else:
            seeds = list(seed)
            if len(seeds) != self.num_envs:
                raise ValueError("seed: %d seeds, expected one per env (%d)" % (len(seeds), self.num_envs))
        for s in seeds:
            if isinstance(s, bool) or not isinstance(s, (int, np.integer)) or not 0 <= int(s) < 2 ** 63:
                raise ValueError("seed: %r, expected integers 0 to 2**63-1" % (s,))
        if _gym is not None:
            self._np_random_seed = seeds[0]
        array = np.asarray([int(s) for s in seeds], dtype=np.uint64)
        _check(self._lib.urw_batch_reset(self._handle, array.ctypes.data, array.size, int(max_steps), self._obs.ctypes.data, self._obs.size))
        self._started = True
        return self._obs.copy(), self._infos()

    def step(self, actions):
        """Plays one cycle of every match; actions (num_envs, action_size) integers 0..15 (or flat num_envs * action_size)."""
        if self._handle is None:
            raise RuntimeError("step() after close()")
        if not self._started:
            raise RuntimeError("step() before reset()")
        a = np.asarray(actions)
        if a.size != self._actions.size or a.shape not in ((self.num_envs, self.action_size), (self._actions.size,)):
            raise ValueError("actions: shape %s, expected (%d, %d) (num_envs, 2 codes per fish of the team)" % (a.shape, self.num_envs, self.action_size))
        if a.dtype.kind == "f":
            bad = ~np.isfinite(a)
            if bad.any():
                raise ValueError("actions: %s at %s, expected integers 0..15" % (a[bad][0], _where(bad, self.action_size)))
            bad = a != np.floor(a)
            if bad.any():
                raise ValueError("actions: %s at %s is not an integer" % (a[bad][0], _where(bad, self.action_size)))
        elif a.dtype.kind not in "iub":
            raise ValueError("actions: dtype %s, expected integers 0..15" % a.dtype)
        bad = (a < 0) | (a > 15)
        if bad.any():
            raise ValueError("actions: %s at %s, expected integers 0..15" % (a[bad][0], _where(bad, self.action_size)))
        np.copyto(self._actions, a.reshape(self._actions.shape), casting="unsafe")
        _check(self._lib.urw_batch_step(*self._step_args))
        return self._obs.copy(), self._rewards.copy(), self._terminated.copy(), self._truncated.copy(), self._infos()

    def close(self, **kwargs):
        if getattr(self, "_handle", None) is not None:
            self._lib.urw_batch_destroy(self._handle)
            self._handle = None

    def __del__(self):
        self.close()

    # -- info --------------------------------------------------------------------------------

    def _infos(self) -> Dict[str, Any]:
        _check(self._lib.urw_batch_info(self._handle, self._cycles.ctypes.data, self._goals.ctypes.data, self._seeds.ctypes.data, self.num_envs))
        return {"cycle": self._cycles.copy(), "goals": self._goals.copy(), "seed": self._seeds.copy()}


class FishParallelEnv(_ParallelEnv):
    """One match of `item` in multi-agent form: one agent per fish of team `team`, the other team playing `opponent`.

    PettingZoo's ParallelEnv conventions: possible_agents "fish_0", "fish_1", ... (the team's fish
    in the order of their indices); reset(seed=, options=) -> (observations, infos) and
    step(actions) -> (observations, rewards, terminations, truncations, infos), each a dict keyed by
    agent. Agent k's observation: its own fish's 5 values (x/1000, y/1000, cos and sin of its
    heading, speed/1000) followed by the match's observation (FishVecEnv's row). Its action: 2
    integers 0..15 (speed code, turn code). Every agent gets the team's reward (the change of own
    score minus the other team's) and the same flags; when the episode ends `agents` becomes empty
    and the next episode needs reset(). infos per agent: "cycle", "goals" (team 0's and team 1's
    score), "seed". state(): the match's observation.
    """

    metadata = {"render_modes": [], "name": "urwpgsim2d_fish_parallel_v0", "is_parallelizable": True}

    def __init__(self, item: str = "polo-3v3", opponent: str = "chase-ball", team: int = 0, cycles: int = 600):
        self._vec = FishVecEnv(item, opponent, num_envs=1, team=team, cycles=cycles)
        self.item, self.opponent, self.team, self.cycles = self._vec.item, opponent, self._vec.team, self._vec.cycles
        count = self._vec.action_size // 2
        self.possible_agents = ["fish_%d" % k for k in range(count)]
        self.agents = []
        first = _first_fish_of_team(item, team)
        self._own = {agent: slice(5 * (first + k), 5 * (first + k) + 5) for k, agent in enumerate(self.possible_agents)}
        size = 5 + self._vec.observation_size
        if _gym is not None:
            self.observation_spaces = {a: _gym.spaces.Box(-1e4, 1e4, shape=(size,), dtype=np.float32) for a in self.possible_agents}
            self.action_spaces = {a: _gym.spaces.MultiDiscrete([16, 16]) for a in self.possible_agents}
            self.state_space = _gym.spaces.Box(-1e4, 1e4, shape=(self._vec.observation_size,), dtype=np.float32)
        else:
            self.observation_spaces = {a: _Box(-1e4, 1e4, (size,)) for a in self.possible_agents}
            self.action_spaces = {a: _MultiDiscrete([16, 16]) for a in self.possible_agents}
            self.state_space = _Box(-1e4, 1e4, (self._vec.observation_size,))
        self._state = np.zeros(self._vec.observation_size, dtype=np.float32)
        self._actions = np.zeros((1, self._vec.action_size), dtype=np.int64)

    def observation_space(self, agent: str):
        return self.observation_spaces[self._known(agent, "agent")]

    def action_space(self, agent: str):
        return self.action_spaces[self._known(agent, "agent")]

    def reset(self, seed: Optional[int] = None, options: Optional[Dict[str, Any]] = None):
        """Starts the match: seed an int (or None: random); options {"max_steps": n} cuts the episode after n steps."""
        if seed is not None and (isinstance(seed, bool) or not isinstance(seed, (int, np.integer))):
            raise ValueError("seed: %r, expected an integer 0 to 2**63-1 or None" % (seed,))
        obs, infos = self._vec.reset(seed=None if seed is None else [int(seed)], options=options)
        self.agents = list(self.possible_agents)
        return self._observations(obs[0]), self._infos(infos)

    def step(self, actions: Dict[str, Any]):
        """Plays one cycle: actions {agent: (speed code, turn code)} for every agent of `agents`."""
        if not self.agents:
            raise RuntimeError("step() with no agents: call reset() first (the episode ended, or none started)")
        if not isinstance(actions, dict):
            raise ValueError("actions: %s, expected a dict {agent: (speed code, turn code)}" % type(actions).__name__)
        for agent in actions:
            self._known(agent, "actions")
        for k, agent in enumerate(self.agents):
            if agent not in actions:
                raise ValueError("actions: no action for %r (agents: %s)" % (agent, ", ".join(self.agents)))
            self._actions[0, 2 * k:2 * k + 2] = _codes(actions[agent], "actions[%r]" % agent)
        obs, rewards, terminations, truncations, infos = self._vec.step(self._actions)
        agents = self.agents
        reward, terminated, truncated = float(rewards[0]), bool(terminations[0]), bool(truncations[0])
        if terminated or truncated:
            self.agents = []
        return (self._observations(obs[0], agents), {a: reward for a in agents}, {a: terminated for a in agents},
                {a: truncated for a in agents}, self._infos(infos, agents))

    def state(self) -> np.ndarray:
        """The match's observation (FishVecEnv's row): every fish, every ball, the time fraction."""
        return self._state.copy()

    def render(self):
        return None

    def close(self):
        self._vec.close()

    def _known(self, agent, name: str) -> str:
        if agent not in self._own:
            raise ValueError("%s: unknown agent %r (agents: %s)" % (name, agent, ", ".join(self.possible_agents)))
        return agent

    def _observations(self, row: np.ndarray, agents=None) -> Dict[str, np.ndarray]:
        self._state[:] = row
        return {a: np.concatenate((row[self._own[a]], row)) for a in (agents if agents is not None else self.agents)}

    def _infos(self, infos, agents=None) -> Dict[str, Dict[str, Any]]:
        one = {"cycle": int(infos["cycle"][0]), "goals": tuple(int(g) for g in infos["goals"][0]), "seed": int(infos["seed"][0])}
        return {a: dict(one) for a in (agents if agents is not None else self.agents)}


def _codes(action, name: str) -> np.ndarray:
    """One fish's action as 2 integers 0..15, or a ValueError naming it."""
    a = np.asarray(action)
    if a.shape != (2,):
        raise ValueError("%s: shape %s, expected (2,) (speed code, turn code)" % (name, a.shape))
    if a.dtype.kind == "f":
        bad = ~np.isfinite(a) | (a != np.floor(np.nan_to_num(a)))
        if bad.any():
            raise ValueError("%s: %s at [%d], expected integers 0..15" % (name, a[bad][0], int(np.flatnonzero(bad)[0])))
    elif a.dtype.kind not in "iub":
        raise ValueError("%s: dtype %s, expected integers 0..15" % (name, a.dtype))
    bad = (a < 0) | (a > 15)
    if bad.any():
        raise ValueError("%s: %s at [%d], expected integers 0..15" % (name, a[bad][0], int(np.flatnonzero(bad)[0])))
    return a.astype(np.int64)


def _first_fish_of_team(item: str, team: int) -> int:
    """The index of the team's first fish in the observation: every item lists its fish team by team (team 0 first)."""
    first = 0
    for other in range(int(team)):
        handle = ctypes.c_void_p()
        _check(_lib.urw_batch_create(item.encode("utf-8"), b"idle", 1, other, 1, ctypes.byref(handle)))
        fish = ctypes.c_int32()
        try:
            _check(_lib.urw_batch_sizes(handle, None, None, None, ctypes.byref(fish)))
        finally:
            _lib.urw_batch_destroy(handle)
        first += fish.value
    return first


def _where(bad, width: int) -> str:
    index = int(np.flatnonzero(bad.reshape(-1))[0])
    return "[%d, %d]" % (index // width, index % width)
