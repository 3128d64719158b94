import os
import tempfile
import unittest

from urwpgsim2d.env import FishEnv


class FishEnvTests(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.env = FishEnv(item="polo-1v1", opponent="chase-ball", cycles=60)

    @classmethod
    def tearDownClass(cls):
        cls.env.close()

    def test_the_gymnasium_contract(self):
        env = self.env
        obs, info = env.reset(seed=3)
        self.assertEqual(len(obs), env.observation_space.shape[0])
        self.assertEqual(list(env.action_space.nvec), [16, 16])
        self.assertEqual(info["cycle"], 0)
        steps, total = 0, 0.0
        while True:
            obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
            steps += 1
            total += reward
            self.assertEqual(len(obs), env.observation_space.shape[0])
            if terminated or truncated:
                break
        self.assertLessEqual(steps, 60)
        if terminated:
            self.assertEqual(info["end"]["faults"], 0)
            goals = info["end"]["goals"]
            self.assertEqual(total, goals[0] - goals[1])
            self.assertEqual(steps, info["end"]["cycle"])
        else:
            self.assertEqual(steps, 60)
            self.assertEqual(total, info["goals"][0] - info["goals"][1])
        with self.assertRaises(RuntimeError):
            env.step([0, 7])

    def test_an_episode_is_cut_at_its_cycles_when_the_item_plays_on(self):
        # Polo after a 0:0 normal time plays extra time and penalties: the episode still ends at `cycles`,
        # truncated, and the time fraction never passes 1.
        env = FishEnv(item="polo-1v1", opponent="idle", cycles=30)
        try:
            obs, _ = env.reset(seed=2)
            steps, fractions = 0, [obs[-1]]
            while True:
                obs, _, terminated, truncated, info = env.step([0, 7])
                steps += 1
                fractions.append(obs[-1])
                if terminated or truncated:
                    break
            self.assertTrue(truncated)
            self.assertFalse(terminated)
            self.assertEqual(steps, 30)
            self.assertEqual(info["cycle"], 30)
            self.assertAlmostEqual(fractions[-1], 1.0)
            self.assertTrue(all(0.0 <= f <= 1.0 for f in fractions))
        finally:
            env.close()

    def test_to_end_plays_past_the_cycles_until_the_match_ends_and_the_server_writes_its_page(self):
        # A 0:0 after 30 cycles goes to extra time, penalties and the clutch shot; with to_end the
        # episode follows the match to its end, and run --html writes the replay page then.
        with tempfile.TemporaryDirectory() as folder:
            page = os.path.join(folder, "match.html")
            env = FishEnv(item="polo-1v1", opponent="idle", cycles=30, run_args=["--html", page])
            try:
                env.reset(seed=2, options={"to_end": True})
                steps = 0
                while True:
                    obs, _, terminated, truncated, info = env.step([0, 7])
                    steps += 1
                    self.assertFalse(truncated)
                    if terminated:
                        break
                self.assertGreater(steps, 30 + 1800)
                self.assertEqual(info["end"]["cycle"], steps)
                self.assertAlmostEqual(float(obs[-1]), 1.0)
                with open(page, encoding="utf-8") as f:
                    self.assertIn("<html", f.read(4096).lower())
                with self.assertRaisesRegex(ValueError, r"options\['to_end'\]: 1, expected True or False"):
                    env.reset(seed=2, options={"to_end": 1})
            finally:
                env.close()

    def test_the_same_seed_and_actions_give_the_same_episode(self):
        def episode(seed):
            obs, _ = self.env.reset(seed=seed, options={"max_steps": 25})
            seen = [list(obs)]
            for i in range(25):
                obs, _, _, truncated, _ = self.env.step([(i * 5) % 16, (i * 3) % 16])
                seen.append(list(obs))
            self.assertTrue(truncated)
            return seen

        self.assertEqual(episode(7), episode(7))
        self.assertNotEqual(episode(7)[-1], episode(8)[-1])

    def test_bad_actions_and_options_are_refused(self):
        self.env.reset(seed=1, options={"max_steps": 1})
        for bad in ([16, 7], [1], [1, 2, 3, 4], [-1, 0]):
            with self.assertRaises(ValueError):
                self.env.step(bad)
        with self.assertRaises(ValueError):
            self.env.reset(seed=1, options={"colour": "red"})


if __name__ == "__main__":
    unittest.main()
