# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""A short fuzz run in the suite (two clients at once); the full 1,000,000 is
`python tests/integration/fuzz.py`."""

import time

from fuzz import Fuzzer


def test_malformed_directives_get_defined_codes_and_change_nothing(tmp_path):
    fuzzer = Fuzzer(tmp_path, seed=3, lanes=2)
    started = time.monotonic()
    try:
        fuzzer.run(1500)
        alive = fuzzer.alive()
        differences = fuzzer.differences()
        print(fuzzer.summary(time.monotonic() - started, alive, differences))
        assert alive
        assert fuzzer.undefined == []
        assert fuzzer.unanswered == 0 and fuzzer.codes.get(216, 0) == 0, fuzzer.codes
        # 220 is a defined code, but each one is a defect: input deserves the code of its fault.
        assert fuzzer.codes.get(220, 0) == 0, fuzzer.codes
        assert fuzzer.changed_by_rejected == []
        assert differences == set()
        # About a third of the directives are rejected on a target, and a third acknowledged.
        assert fuzzer.rejected > 400 and fuzzer.codes.get(0, 0) > 100, fuzzer.codes
        assert set(fuzzer.kinds) == {'valid', 'almost', 'hostile'}
    finally:
        fuzzer.close()
