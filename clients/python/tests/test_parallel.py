import math
import unittest

import numpy as np

from urwpgsim2d.vec import FishParallelEnv, FishVecEnv


def scripted(step: int, k: int) -> list:
    return [(step * 3 + 5 * k) % 16, (step + 7 * k) % 16]


class FishParallelEnvTests(unittest.TestCase):
    def test_agents_spaces_shapes_and_dtypes(self):
        env = FishParallelEnv("polo-3v3", "demo", team=0, cycles=20)
        try:
            self.assertEqual(env.possible_agents, ["fish_0", "fish_1", "fish_2"])
            self.assertEqual(env.agents, [])
            for agent in env.possible_agents:
                self.assertEqual(env.observation_space(agent).shape, (5 + 35,))
                self.assertEqual(list(env.action_space(agent).nvec), [16, 16])
            obs, infos = env.reset(seed=4)
            self.assertEqual(env.agents, env.possible_agents)
            self.assertEqual(sorted(obs), env.possible_agents)
            self.assertEqual(sorted(infos), env.possible_agents)
            for agent in env.agents:
                self.assertEqual((obs[agent].shape, obs[agent].dtype), ((40,), np.float32))
                self.assertTrue(env.observation_space(agent).contains(obs[agent]))
                self.assertEqual(infos[agent], {"cycle": 0, "goals": (0, 0), "seed": 4})
            obs, rewards, terminations, truncations, infos = env.step({a: env.action_space(a).sample() for a in env.agents})
            for result in (obs, rewards, terminations, truncations, infos):
                self.assertEqual(sorted(result), env.possible_agents)
            for agent in env.agents:
                self.assertEqual(type(rewards[agent]), float)
                self.assertEqual((terminations[agent], truncations[agent]), (False, False))
                self.assertEqual(infos[agent]["cycle"], 1)
            # The rest of each observation is the match's (FishVecEnv's row, the state).
            state = env.state()
            self.assertEqual(state.shape, (35,))
            for agent in env.agents:
                self.assertTrue(np.array_equal(obs[agent][5:], state))
        finally:
            env.close()

    def test_each_agent_sees_and_moves_its_own_fish(self):
        # Team 1 of polo-1v1: its fish is match fish 1 (values 5..9 of the match's observation).
        env = FishParallelEnv("polo-1v1", "idle", team=1, cycles=100)
        batch = FishVecEnv("polo-1v1", "idle", num_envs=1, team=1, cycles=100)
        try:
            obs, _ = env.reset(seed=9)
            row, _ = batch.reset(seed=9)
            self.assertTrue(np.array_equal(obs["fish_0"][:5], row[0, 5:10]))
            for step in range(30):
                obs, *_ = env.step({"fish_0": [14, 7]})
                row, *_ = batch.step([[14, 7]])
                self.assertTrue(np.array_equal(obs["fish_0"], np.concatenate((row[0, 5:10], row[0]))))
            # Team 1 starts on the right facing left: swimming ahead moves it left, the idle fish 0 stays.
            self.assertLess(obs["fish_0"][0], 0.9)
            self.assertAlmostEqual(float(obs["fish_0"][5]), -1.02, delta=0.1)
        finally:
            env.close()
            batch.close()
        # In 3v3 every agent drives its own fish: only fish_1 swims.
        env = FishParallelEnv("polo-3v3", "idle", team=0, cycles=100)
        try:
            first, _ = env.reset(seed=1)
            for _ in range(30):
                obs, *_ = env.step({"fish_0": [0, 7], "fish_1": [14, 7], "fish_2": [0, 7]})
            moved = {a: math.dist(first[a][:2], obs[a][:2]) for a in env.possible_agents}
            self.assertGreater(moved["fish_1"], 0.3)
            self.assertLess(moved["fish_0"], 0.1)
            self.assertLess(moved["fish_2"], 0.1)
        finally:
            env.close()

    def test_the_same_seed_and_actions_give_the_same_episode(self):
        def episode(seed):
            env = FishParallelEnv("polo-3v3", "chase-ball", cycles=50)
            try:
                obs, _ = env.reset(seed=seed)
                seen = [np.stack([obs[a] for a in env.possible_agents])]
                for step in range(50):
                    obs, *_ = env.step({a: scripted(step, k) for k, a in enumerate(env.agents)})
                    seen.append(np.stack([obs[a] for a in env.possible_agents]))
                return np.stack(seen)
            finally:
                env.close()

        a, b, c = episode(21), episode(21), episode(22)
        self.assertTrue(np.array_equal(a, b))
        self.assertFalse(np.array_equal(a, c))

    def test_agents_are_removed_when_the_episode_ends(self):
        # Truncated: the match's cycles were played (polo plays on after a 0:0).
        env = FishParallelEnv("polo-1v1", "idle", cycles=12)
        try:
            env.reset(seed=2)
            for step in range(1, 13):
                obs, rewards, terminations, truncations, infos = env.step({"fish_0": [7, 7]})
                self.assertEqual(truncations, {"fish_0": step == 12})
                self.assertEqual(env.agents, [] if step == 12 else ["fish_0"])
            self.assertEqual(infos["fish_0"]["cycle"], 12)
            self.assertEqual(float(obs["fish_0"][-1]), 1.0)
            with self.assertRaisesRegex(RuntimeError, "call reset"):
                env.step({"fish_0": [7, 7]})
            # options["max_steps"] cuts earlier; reset starts again.
            env.reset(seed=2, options={"max_steps": 3})
            flags = [env.step({"fish_0": [7, 7]})[3]["fish_0"] for _ in range(3)]
            self.assertEqual(flags, [False, False, True])
        finally:
            env.close()
        # Terminated: ball-grab ends its match (one team of two fish).
        env = FishParallelEnv("ball-grab", "chase-ball", cycles=25)
        try:
            env.reset(seed=2)
            for _ in range(25):
                _, _, terminations, truncations, _ = env.step({a: [14, 7] for a in env.agents})
            self.assertEqual(set(terminations.values()), {True})
            self.assertEqual(set(truncations.values()), {False})
            self.assertEqual(env.agents, [])
        finally:
            env.close()

    def test_bad_input_is_refused_with_a_clear_message(self):
        with self.assertRaisesRegex(ValueError, r'^item: unknown item "polo-2v2"'):
            FishParallelEnv("polo-2v2", "idle")
        with self.assertRaisesRegex(ValueError, r'^opponent: unknown opponent "nobody"'):
            FishParallelEnv("polo-1v1", "nobody")
        env = FishParallelEnv("polo-3v3", "idle", cycles=10)
        try:
            with self.assertRaisesRegex(ValueError, r"^agent: unknown agent 'fish_3' \(agents: fish_0, fish_1, fish_2\)"):
                env.observation_space("fish_3")
            with self.assertRaisesRegex(RuntimeError, "call reset"):
                env.step({})
            with self.assertRaisesRegex(ValueError, r"^seed: 'x', expected an integer"):
                env.reset(seed="x")
            with self.assertRaisesRegex(ValueError, r"^seed: -1, expected integers 0 to 2\*\*63-1"):
                env.reset(seed=-1)
            with self.assertRaisesRegex(ValueError, r"^options: unknown curriculum"):
                env.reset(seed=1, options={"curriculum": 1})
            env.reset(seed=1)
            good = {"fish_0": [1, 7], "fish_1": [1, 7], "fish_2": [1, 7]}
            cases = [
                ([[1, 7]], r"^actions: list, expected a dict"),
                ({"fish_0": [1, 7], "fish_1": [1, 7]}, r"^actions: no action for 'fish_2'"),
                (dict(good, fish_9=[1, 7]), r"^actions: unknown agent 'fish_9'"),
                (dict(good, fish_1=[1, 7, 0]), r"^actions\['fish_1'\]: shape \(3,\), expected \(2,\)"),
                (dict(good, fish_2=[1, 16]), r"^actions\['fish_2'\]: 16 at \[1\], expected integers 0..15"),
                (dict(good, fish_0=[-1, 7]), r"^actions\['fish_0'\]: -1 at \[0\], expected integers 0..15"),
                (dict(good, fish_0=[math.nan, 7.0]), r"^actions\['fish_0'\]: nan at \[0\], expected integers 0..15"),
                (dict(good, fish_0=[1.5, 7.0]), r"^actions\['fish_0'\]: 1.5 at \[0\], expected integers 0..15"),
                (dict(good, fish_0=["a", "b"]), r"^actions\['fish_0'\]: dtype <U1, expected integers 0..15"),
            ]
            for actions, message in cases:
                with self.assertRaisesRegex(ValueError, message):
                    env.step(actions)
            # Nothing was played by a refused step.
            _, _, _, _, infos = env.step(good)
            self.assertEqual(infos["fish_0"]["cycle"], 1)
        finally:
            env.close()


if __name__ == "__main__":
    unittest.main()
