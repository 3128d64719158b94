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
        self.assertTrue(terminated)
        self.assertEqual(info["end"]["faults"], 0)
        goals = info["end"]["goals"]
        self.assertEqual(total, goals[0] - goals[1])
        self.assertEqual(steps, info["end"]["cycle"])
        with self.assertRaises(RuntimeError):
            env.step([0, 7])

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
