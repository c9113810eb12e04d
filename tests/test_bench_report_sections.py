# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""`bench/suite.py --sections` rewrites only the sections it reran (the rest of a report, measured
at other times, stays as it was), and sections 1 to 7, rendered together, go as one block."""

import pathlib
import sys

REPO = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / 'bench'))

import suite  # noqa: E402  (bench/ is scripts, not a package)

OLD = ('# ARMOR for ROS 2: benchmark report\n\nProduced on Monday.\n\n## Summary\n\n| a |\n\n'
       '## 1. Transport overhead\n\nold one\n\n## 7. Reasoning at robot speed (issue 15)\n\n'
       'old seven\n\n## 8. Plain rclpy clients\n\nold eight\n\n## 12. Explanations\n\nold twelve\n')


def _section(report: str, number: int) -> str:
    start = report.index(f'\n## {number}. ')
    end = report.find('\n## ', start + 1)
    return report[start:end if end >= 0 else len(report)]


def test_a_rerun_section_replaces_its_old_text_and_a_new_one_goes_in_number_order():
    rewritten = suite._replace_sections(OLD, {12: '## 12. Explanations\n\nnew twelve\n',
                                              9: '## 9. Real shapes\n\nnine\n'})
    assert 'old twelve' not in rewritten and 'new twelve' in _section(rewritten, 12)
    assert rewritten.index('## 8.') < rewritten.index('## 9.') < rewritten.index('## 12.')
    for kept in ('Produced on Monday.', 'old one', 'old seven', 'old eight'):
        assert kept in rewritten, kept
    assert '\n\n\n' not in rewritten and rewritten.endswith('twelve\n')


def test_a_new_head_replaces_the_summary_and_sections_one_to_seven_only():
    head = ('# ARMOR for ROS 2: benchmark report\n\nProduced on Friday.\n\n## Summary\n\n| b |\n\n'
            '## 1. Transport overhead\n\nnew one\n')
    rewritten = suite._replace_sections(OLD, {}, head)
    assert 'Produced on Friday.' in rewritten and 'Produced on Monday.' not in rewritten
    assert 'old one' not in rewritten and 'old seven' not in rewritten
    assert _section(rewritten, 8).strip().endswith('old eight')
    assert _section(rewritten, 12).strip().endswith('old twelve')


def test_an_explanations_row_that_measured_nothing_fails_the_suite():
    from answers import wrong_in
    rows = [{'map': 'robotics', 'individuals': 1000, 'kind': 'class', 'right': 20, 'wrong': []},
            {'map': 'robotics', 'individuals': 10000, 'kind': 'class',
             'error': 'java.lang.NoClassDefFoundError: io/github/armor/core/JustificationCheck'}]
    wrong = wrong_in({'explanations': {'rows': rows}})
    assert wrong == ['12. explanations, robotics, 10000, class: no answer: '
                     'java.lang.NoClassDefFoundError: io/github/armor/core/JustificationCheck']
