"""Runs the Python client's tests (unittest) and ends with a line in the form CI counts: 'Failed: N, Passed: N, Skipped: N, Total: N'."""

import os
import sys
import unittest

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
suite = unittest.defaultTestLoader.discover(os.path.join(here, "tests"), top_level_dir=here)
result = unittest.TextTestRunner(verbosity=2).run(suite)
failed = len(result.failures) + len(result.errors) + len(result.unexpectedSuccesses)
skipped = len(result.skipped) + len(result.expectedFailures)
passed = result.testsRun - failed - skipped
print("Python client - Failed: %d, Passed: %d, Skipped: %d, Total: %d" % (failed, passed, skipped, result.testsRun))
sys.exit(0 if failed == 0 and skipped == 0 and result.testsRun > 0 else 1)
