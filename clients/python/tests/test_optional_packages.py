"""The environments subclass gymnasium's and pettingzoo's classes when those can be imported, and work without them.

Neither package needs to be installed: each test runs Python in a subprocess with small stand-in
packages of the same names (only what the environments use) first on sys.path, or with packages of
those names that fail to import.
"""

import os
import subprocess
import sys
import tempfile
import textwrap
import unittest

CLIENT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

FAKE_GYMNASIUM = {
    "gymnasium/__init__.py": """
        from . import spaces, vector
        FAKE = True

        class Env:
            def reset(self, *, seed=None, options=None):
                self.reset_seed = seed
    """,
    "gymnasium/spaces.py": """
        import numpy as np

        class Box:
            def __init__(self, low, high, shape=None, dtype=np.float32):
                self.low, self.high, self.shape, self.dtype = low, high, tuple(shape), np.dtype(dtype)

        class MultiDiscrete:
            def __init__(self, nvec):
                self.nvec = np.asarray(nvec, dtype=np.int64)
                self.shape = self.nvec.shape
    """,
    "gymnasium/vector/__init__.py": """
        from . import utils

        class VectorEnv:
            pass
    """,
    "gymnasium/vector/utils.py": """
        import numpy as np
        from ..spaces import Box, MultiDiscrete

        def batch_space(space, n):
            if isinstance(space, Box):
                return Box(space.low, space.high, shape=(n,) + space.shape, dtype=space.dtype)
            return MultiDiscrete(np.tile(space.nvec, (n, 1)))
    """,
}

FAKE_PETTINGZOO = {
    "pettingzoo/__init__.py": """
        class ParallelEnv:
            fake = True
    """,
}

ABSENT = {
    "gymnasium/__init__.py": "raise ImportError('not installed (test)')\n",
    "pettingzoo/__init__.py": "raise ImportError('not installed (test)')\n",
}


def run_with(packages: dict, script: str) -> str:
    """Runs script in a fresh python3 with `packages` (path -> source) first on sys.path; returns its stdout."""
    with tempfile.TemporaryDirectory() as folder:
        for path, source in packages.items():
            full = os.path.join(folder, path)
            os.makedirs(os.path.dirname(full), exist_ok=True)
            with open(full, "w") as f:
                f.write(textwrap.dedent(source))
        env = dict(os.environ, PYTHONPATH=os.pathsep.join([folder, CLIENT]))
        done = subprocess.run([sys.executable, "-c", textwrap.dedent(script)], env=env, capture_output=True, text=True, timeout=120)
    if done.returncode != 0:
        raise AssertionError("the script failed:\n" + done.stderr[-3000:])
    return done.stdout


class OptionalPackagesTests(unittest.TestCase):
    def test_with_gymnasium_and_pettingzoo_the_environments_are_theirs(self):
        out = run_with({**FAKE_GYMNASIUM, **FAKE_PETTINGZOO}, """
            import gymnasium, pettingzoo
            from urwpgsim2d.env import FishEnv
            from urwpgsim2d.vec import FishParallelEnv, FishVecEnv
            assert gymnasium.FAKE and pettingzoo.ParallelEnv.fake
            assert issubclass(FishEnv, gymnasium.Env)
            assert issubclass(FishVecEnv, gymnasium.vector.VectorEnv)
            assert issubclass(FishParallelEnv, pettingzoo.ParallelEnv)
            env = FishVecEnv("polo-3v3", "idle", num_envs=4, cycles=5)
            Box, MultiDiscrete = gymnasium.spaces.Box, gymnasium.spaces.MultiDiscrete
            assert type(env.single_observation_space) is Box and env.single_observation_space.shape == (35,)
            assert type(env.single_action_space) is MultiDiscrete and list(env.single_action_space.nvec) == [16] * 6
            assert type(env.observation_space) is Box and env.observation_space.shape == (4, 35)
            assert type(env.action_space) is MultiDiscrete and env.action_space.shape == (4, 6)
            obs, _ = env.reset(seed=3)
            assert obs.shape == (4, 35) and env._np_random_seed == 3
            env.close()
            par = FishParallelEnv("polo-3v3", "idle", cycles=5)
            for agent in par.possible_agents:
                assert type(par.observation_space(agent)) is Box and par.observation_space(agent).shape == (40,)
                assert type(par.action_space(agent)) is MultiDiscrete and list(par.action_space(agent).nvec) == [16, 16]
            assert type(par.state_space) is Box
            obs, _ = par.reset(seed=3)
            assert sorted(obs) == ["fish_0", "fish_1", "fish_2"]
            par.close()
            print("subclassed")
        """)
        self.assertEqual(out.strip(), "subclassed")

    def test_without_them_the_environments_use_stand_ins(self):
        out = run_with(ABSENT, """
            from urwpgsim2d import env as single, vec
            from urwpgsim2d.vec import FishParallelEnv, FishVecEnv
            assert single._gym is None and vec._gym is None
            assert FishVecEnv.__bases__ == (object,) and FishParallelEnv.__bases__ == (object,)
            assert single.FishEnv.__bases__ == (object,)
            env = FishVecEnv("polo-1v1", "idle", num_envs=2, cycles=5)
            assert type(env.single_observation_space).__name__ == "_Box"
            action = env.action_space.sample()
            assert env.action_space.contains(action) and action.shape == (2, 2)
            env.close()
            par = FishParallelEnv("polo-1v1", "idle", cycles=5)
            assert type(par.action_space("fish_0")).__name__ == "_MultiDiscrete"
            par.close()
            print("stand-ins")
        """)
        self.assertEqual(out.strip(), "stand-ins")


if __name__ == "__main__":
    unittest.main()
