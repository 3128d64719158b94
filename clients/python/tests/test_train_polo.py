"""The training example (urwpgsim2d.examples.train_polo): a few iterations run end to end, and its parts against independent truth.

The full run (12 minutes of training) is measured in docs/learning.md; here it trains for two
iterations on short episodes, which checks that every step runs and writes its files.
"""

import contextlib
import io
import os
import struct
import tempfile
import unittest
import zlib

import numpy as np

from tests.test_optional_packages import run_with
from urwpgsim2d.examples import train_polo


def read_png(path: str):
    """(width, height, pixels as bytes per row) of an 8-bit RGB PNG with filter 0 rows."""
    with open(path, "rb") as f:
        data = f.read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    at, chunks = 8, {}
    while at < len(data):
        (length,) = struct.unpack(">I", data[at:at + 4])
        kind, body = data[at + 4:at + 8], data[at + 8:at + 8 + length]
        assert struct.unpack(">I", data[at + 8 + length:at + 12 + length])[0] == zlib.crc32(kind + body) & 0xFFFFFFFF, "bad CRC"
        chunks[kind] = chunks.get(kind, b"") + body
        at += 12 + length
    width, height = struct.unpack(">II", chunks[b"IHDR"][:8])
    return width, height, chunks


class TrainPoloTests(unittest.TestCase):
    def run_example(self, *args):
        folder = tempfile.mkdtemp(prefix="train_polo")
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            code = train_polo.main(["--iterations", "2", "--envs", "4", "--episodes", "3", "--episode-cycles", "80",
                                    "--replay-cycles", "20", "--out", folder, *args])
        self.assertEqual(code, 0)
        return folder, out.getvalue()

    def check_outputs(self, folder: str, printed: str, drawn_by: str):
        self.assertRegex(printed, r"episodes with a goal \(3 seeded episodes of 80 cycles\): trained \d+% \(sampled actions \d+%\), random \d+%")
        # Episodes of 80 cycles are 20 decisions: each rollout of 64 decisions finishes 3 of them.
        self.assertEqual(printed.count("episode return"), 6)
        self.assertIn("(%s)" % drawn_by, printed)
        width, height, chunks = read_png(os.path.join(folder, "curve.png"))
        self.assertGreater(width, 300)
        self.assertGreater(height, 200)
        self.assertIn(b"IEND", chunks)
        with open(os.path.join(folder, "curve.svg"), encoding="utf-8") as f:
            svg = f.read()
        self.assertTrue(svg.startswith("<svg ") and svg.rstrip().endswith("</svg>"))
        self.assertEqual(svg.count("<polyline"), 2)
        with open(os.path.join(folder, "replay.html"), encoding="utf-8") as f:
            page = f.read()
        self.assertIn("<html", page[:4096].lower())
        self.assertRegex(printed, r"replay\.html: a match of the trained fish against idle \(seed 7\), \d+ cycles, \d+:0")

    def test_numpy_training_runs_and_writes_the_curve_and_the_replay_page(self):
        folder, printed = self.run_example("--backend", "numpy", "--plot", "builtin")
        self.assertIn("PPO in numpy", printed)
        self.check_outputs(folder, printed, "built-in PNG writer")

    def test_torch_training_runs_and_matplotlib_draws_the_curve(self):
        folder, printed = self.run_example("--backend", "torch", "--plot", "auto")
        self.assertIn("PPO in torch", printed)
        self.check_outputs(folder, printed, "matplotlib")

    def test_without_torch_and_matplotlib_it_uses_numpy_and_its_own_png_writer(self):
        absent = {"torch/__init__.py": "raise ImportError('not installed (test)')\n",
                  "matplotlib/__init__.py": "raise ImportError('not installed (test)')\n"}
        out = run_with(absent, """
            import os, tempfile
            from urwpgsim2d.examples import train_polo
            agent = train_polo.make_agent("auto", seed=1, lr=1e-3)
            path = os.path.join(tempfile.mkdtemp(), "curve.png")
            print(agent.name, train_polo.plot_curve(path, [(0, 1.0, 0.5, 0.0), (1, 2.0, 1.5, 0.25)]), os.path.getsize(path) > 100)
        """)
        self.assertEqual(out.strip(), "numpy built-in PNG writer True")

    def test_the_png_writer_writes_the_pixels_it_is_given(self):
        # Pillow (installed with matplotlib) decodes the file.
        from PIL import Image

        pixels = np.random.default_rng(3).integers(0, 256, (7, 11, 3), dtype=np.uint8)
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "p.png")
            train_polo.write_png(path, pixels)
            with Image.open(path) as image:
                self.assertEqual((image.mode, image.size), ("RGB", (11, 7)))
                self.assertTrue(np.array_equal(np.asarray(image), pixels))

    def test_the_numpy_gradients_are_pytorchs(self):
        # The hand-written back-propagation of PPO's losses against PyTorch's autograd on the same weights.
        import torch

        agent = train_polo.NumpyAgent(seed=5, lr=1e-3)
        rng = np.random.default_rng(6)
        n = 50
        f = rng.normal(size=(n, train_polo.FEATURES))
        a = rng.integers(0, len(train_polo.ACTIONS), n)
        p = agent.probabilities(f)
        # Old probabilities a little off, so some ratios are clipped.
        old = np.log(p[np.arange(n), a]) + rng.normal(0, 0.3, n)
        adv, ret = rng.normal(size=n), rng.normal(size=n)
        mine = agent.policy_gradients(f, a, old, adv, clip=0.2, entropy=0.05)
        mine_v = agent.value_gradients(f, ret)

        def torch_net(params):
            return {k: torch.tensor(v, requires_grad=True) for k, v in params.items()}

        def forward(t, x):
            h = torch.tanh(x @ t["w0"] + t["b0"])
            h = torch.tanh(h @ t["w1"] + t["b1"])
            return h @ t["w2"] + t["b2"]

        x = torch.tensor(f)
        t = torch_net(agent.pi.p)
        logp = torch.log_softmax(forward(t, x), dim=1)
        ratio = torch.exp(logp[torch.arange(n), torch.tensor(a)] - torch.tensor(old))
        adv_t = torch.tensor(adv)
        loss = -torch.min(ratio * adv_t, torch.clamp(ratio, 0.8, 1.2) * adv_t).mean() - 0.05 * (-(logp.exp() * logp).sum(1)).mean()
        loss.backward()
        clipped = int(((ratio > 1.2) | (ratio < 0.8)).sum())
        self.assertGreater(clipped, 0)
        for k in t:
            self.assertTrue(np.allclose(mine[k], t[k].grad.numpy(), rtol=1e-7, atol=1e-10), k)
        tv = torch_net(agent.vf.p)
        (0.5 * ((forward(tv, x)[:, 0] - torch.tensor(ret)) ** 2).mean()).backward()
        for k in tv:
            self.assertTrue(np.allclose(mine_v[k], tv[k].grad.numpy(), rtol=1e-7, atol=1e-10), k)

    def test_features_see_the_field_mirrored_when_attacking_left(self):
        # A fish at (-0.5, 0.2) facing +x with the ball ahead, attacking right, sees what the fish at
        # (0.5, -0.2) facing -x sees attacking left: the same features.
        row = np.zeros((1, 15), dtype=np.float32)
        row[0, :5] = [-0.5, 0.2, 1.0, 0.0, 0.1]
        row[0, 5:10] = [1.0, 0.0, -1.0, 0.0, 0.0]
        row[0, 10:12] = [0.1, 0.3]
        mirrored = row.copy()
        mirrored[0, [0, 1, 2, 3, 5, 6, 7, 8, 10, 11]] *= -1
        last = np.array([4])
        self.assertTrue(np.allclose(train_polo.features(row, last), train_polo.features(mirrored, last, side=-1.0)))
        f = train_polo.features(row, last)[0]
        # The ball is 0.6 ahead and 0.1 across, on the +y side (where turn codes above 7 turn a fish facing +x).
        self.assertAlmostEqual(f[0], 0.6, places=6)
        self.assertAlmostEqual(f[1], 0.1, places=6)
        self.assertEqual(f[-len(train_polo.ACTIONS) + 4], 1.0)


if __name__ == "__main__":
    unittest.main()
