import math
import unittest

import numpy as np

from urwpgsim2d.env import FishEnv
from urwpgsim2d.vec import FishVecEnv


def scripted(step: int, env: int, size: int) -> list:
    return [((step * 5) + (3 * j) + env) % 16 for j in range(size)]


class FishVecEnvTests(unittest.TestCase):
    def test_shapes_dtypes_and_spaces(self):
        env = FishVecEnv("polo-3v3", "demo", num_envs=4, team=1, cycles=20)
        try:
            self.assertEqual(env.num_envs, 4)
            self.assertEqual(env.single_observation_space.shape, (5 * 6 + 4 + 1,))
            self.assertEqual(env.observation_space.shape, (4, 35))
            self.assertEqual(list(env.single_action_space.nvec), [16] * 6)
            self.assertEqual(env.action_space.shape, (4, 6))
            obs, infos = env.reset(seed=1)
            self.assertEqual((obs.shape, obs.dtype), ((4, 35), np.float32))
            self.assertTrue(np.all(obs[:, -1] == 0.0))
            self.assertEqual(list(infos["seed"]), [1, 2, 3, 4])
            self.assertEqual(list(infos["cycle"]), [0, 0, 0, 0])
            action = env.action_space.sample()
            self.assertTrue(env.action_space.contains(action))
            obs, rewards, terminations, truncations, infos = env.step(action)
            self.assertEqual((obs.shape, obs.dtype), ((4, 35), np.float32))
            self.assertEqual((rewards.shape, rewards.dtype), ((4,), np.float32))
            self.assertEqual((terminations.shape, terminations.dtype), ((4,), np.bool_))
            self.assertEqual((truncations.shape, truncations.dtype), ((4,), np.bool_))
            self.assertEqual(infos["goals"].shape, (4, 2))
            self.assertEqual(list(infos["cycle"]), [1, 1, 1, 1])
            self.assertTrue(np.allclose(obs[:, -1], 1 / 20))
            # Headings are unit vectors, positions inside the pool.
            fish = obs[:, :30].reshape(4, 6, 5)
            self.assertTrue(np.allclose(fish[:, :, 2] ** 2 + fish[:, :, 3] ** 2, 1.0, atol=1e-5))
            self.assertTrue(np.all(np.abs(fish[:, :, 0]) < 1.6))
        finally:
            env.close()

    def test_the_same_seeds_and_actions_give_the_same_episodes(self):
        def episodes(seed):
            env = FishVecEnv("polo-1v1", "chase-ball", num_envs=3, cycles=40)
            try:
                obs, _ = env.reset(seed=seed)
                seen = [obs]
                for step in range(40):
                    obs, rewards, _, _, _ = env.step([scripted(step, i, 2) for i in range(3)])
                    seen.append(obs)
                return np.stack(seen)
            finally:
                env.close()

        a, b, c = episodes(7), episodes(7), episodes(8)
        self.assertTrue(np.array_equal(a, b))
        # Seed 8 is env 0's of the second run: env 1 of the first run played seed 8 with other actions.
        self.assertFalse(np.array_equal(a[:, 0], c[:, 0]))
        self.assertTrue(np.array_equal(a[0, 1], c[0, 0]))

    def test_truncation_at_the_matchs_end_then_next_step_autoreset(self):
        # Polo after a 0:0 normal time plays on (extra time): the episode is cut at `cycles`.
        env = FishVecEnv("polo-1v1", "idle", num_envs=2, cycles=30)
        try:
            env.reset(seed=[11, 12])
            for step in range(1, 31):
                obs, rewards, terminations, truncations, infos = env.step(np.full((2, 2), 7))
                self.assertEqual(list(truncations), [step == 30] * 2)
                self.assertFalse(terminations.any())
            self.assertTrue(np.all(obs[:, -1] == 1.0))
            self.assertEqual(list(infos["cycle"]), [30, 30])
            obs, rewards, terminations, truncations, infos = env.step(np.full((2, 2), 15))
            self.assertEqual(list(rewards), [0.0, 0.0])
            self.assertFalse(terminations.any() or truncations.any())
            self.assertEqual(list(infos["cycle"]), [0, 0])
            self.assertTrue(np.all(obs[:, -1] == 0.0))
            self.assertNotEqual(list(infos["seed"]), [11, 12])
            fresh = FishVecEnv("polo-1v1", "idle", num_envs=2, cycles=30)
            first, _ = fresh.reset(seed=[int(s) for s in infos["seed"]])
            fresh.close()
            self.assertTrue(np.array_equal(first, obs))
            # options["max_steps"] cuts earlier.
            env.reset(seed=1, options={"max_steps": 3})
            flags = [env.step(np.zeros((2, 2), dtype=np.int64))[3] for _ in range(3)]
            self.assertEqual([list(f) for f in flags], [[False, False], [False, False], [True, True]])
        finally:
            env.close()

    def test_a_match_the_item_ends_is_terminated(self):
        env = FishVecEnv("ball-grab", "chase-ball", num_envs=1, cycles=25)
        try:
            env.reset(seed=2)
            for step in range(1, 26):
                _, _, terminations, truncations, _ = env.step([[14, 7] * (env.action_size // 2)])
            self.assertEqual((bool(terminations[0]), bool(truncations[0])), (True, False))
        finally:
            env.close()

    def test_the_same_episodes_as_fishenv_over_tcp(self):
        # FishEnv plays `run` in a server process: the in-process batch plays the same matches.
        cycles = 60
        served = FishEnv(item="polo-1v1", opponent="chase-ball", cycles=cycles)
        env = FishVecEnv("polo-1v1", "chase-ball", num_envs=2, cycles=cycles)
        try:
            for seed in (5, 9):
                expected = [list(served.reset(seed=seed)[0])]
                rewards, ends = [], []
                for step in range(cycles):
                    obs, reward, terminated, truncated, _ = served.step(scripted(step, 0, 2))
                    expected.append(list(obs))
                    rewards.append(reward)
                    ends.append((terminated, truncated))
                    if terminated or truncated:
                        break
                obs, _ = env.reset(seed=[seed, seed + 100])
                mine = [obs[0]]
                for step in range(len(rewards)):
                    obs, r, term, trunc, _ = env.step([scripted(step, 0, 2), [0, 7]])
                    mine.append(obs[0])
                    self.assertEqual(float(r[0]), rewards[step])
                    self.assertEqual((bool(term[0]), bool(trunc[0])), ends[step])
                # The same values up to float32 rounding (the server's JSON carries float32 values as decimals).
                compared = len(expected) - (1 if ends[-1][0] else 0)  # FishEnv repeats the last observation when the match ends
                for a, b in zip(expected[:compared], mine[:compared]):
                    self.assertTrue(np.allclose(np.asarray(a, dtype=np.float32), b, rtol=1e-6, atol=1e-6), (a, b))
                moved = np.abs(np.asarray(expected[compared - 1][:2]) - np.asarray(expected[0][:2])).max()
                self.assertGreater(moved, 0.05)
        finally:
            served.close()
            env.close()

    def test_bad_arguments_are_refused_with_a_clear_message(self):
        with self.assertRaisesRegex(ValueError, r'^item: unknown item "polo-2v2"'):
            FishVecEnv("polo-2v2", "idle")
        with self.assertRaisesRegex(ValueError, r'^opponent: unknown opponent "chaser"'):
            FishVecEnv("polo-1v1", "chaser")
        with self.assertRaisesRegex(ValueError, r"^count: 0 matches"):
            FishVecEnv("polo-1v1", "idle", num_envs=0)
        with self.assertRaisesRegex(ValueError, r"^team: 3"):
            FishVecEnv("polo-1v1", "idle", team=3)
        with self.assertRaisesRegex(TypeError, r"num_envs must be an integer"):
            FishVecEnv("polo-1v1", "idle", num_envs=2.5)
        env = FishVecEnv("polo-1v1", "idle", num_envs=2, cycles=10)
        try:
            with self.assertRaisesRegex(RuntimeError, "before reset"):
                env.step(np.zeros((2, 2)))
            env.reset(seed=3)
            with self.assertRaisesRegex(ValueError, r"^actions: shape \(2, 3\), expected \(2, 2\)"):
                env.step(np.zeros((2, 3)))
            with self.assertRaisesRegex(ValueError, r"^actions: nan at \[1, 0\], expected integers 0..15"):
                env.step(np.array([[1.0, 7.0], [math.nan, 7.0]]))
            with self.assertRaisesRegex(ValueError, r"^actions: 16 at \[0, 1\], expected integers 0..15"):
                env.step([[0, 16], [0, 7]])
            with self.assertRaisesRegex(ValueError, r"^actions: 2.5 at \[0, 0\] is not an integer"):
                env.step([[2.5, 7], [0, 7]])
            with self.assertRaisesRegex(ValueError, r"^seed: 3 seeds, expected one per env \(2\)"):
                env.reset(seed=[1, 2, 3])
            with self.assertRaisesRegex(ValueError, r"^options: unknown bogus"):
                env.reset(seed=1, options={"bogus": 1})
            # Nothing was played by a refused step.
            _, infos = env.reset(seed=3)
            self.assertEqual(list(infos["cycle"]), [0, 0])
        finally:
            env.close()
        with self.assertRaisesRegex(RuntimeError, "after close"):
            env.step(np.zeros((2, 2)))


if __name__ == "__main__":
    unittest.main()
