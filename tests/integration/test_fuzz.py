# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""A short fuzz run in the suite; the full 100,000 is `python tests/integration/fuzz.py`."""

from fuzz import Fuzzer


def test_malformed_directives_get_defined_codes_and_change_nothing(tmp_path):
    fuzzer = Fuzzer(tmp_path, seed=3)
    try:
        fuzzer.run(1500)
        assert fuzzer.alive()
        assert fuzzer.undefined == []
        assert fuzzer.differences() == set()
        rejected = sum(n for code, n in fuzzer.codes.items() if code != 0)
        assert rejected > 1000 and fuzzer.codes.get(0, 0) > 20, fuzzer.codes
    finally:
        fuzzer.close()
