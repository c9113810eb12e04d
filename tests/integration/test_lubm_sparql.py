# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""QUERY SPARQL over ROS 2 on one LUBM department (bench/data/lubm, Openllet, after REASON).

The 14 LUBM queries answer exactly the rows published with them (asserted plus inferred
knowledge), asked twice (the second time from the graph the first query made), and the first
query after a change sees it.
"""

import json
import shutil

from conftest import REPO
from test_contract_support import answer, succeeded
from test_contract_support import load  # noqa: F401 (fixture)

LUBM = REPO / 'bench' / 'data' / 'lubm'
DEPARTMENT = 'http://www.Department0.University0.edu'
UB = 'http://swat.cse.lehigh.edu/onto/univ-bench.owl#'


def test_the_14_lubm_queries_answer_the_published_rows(call, load, armor_node):
    department = armor_node.scratch / 'university0-department0.owl'
    shutil.copy2(LUBM / 'university0-department0.owl', department)
    queries = json.loads((LUBM / 'queries.json').read_text())
    reference = load('PELLET', path=department, prefix='lubm')
    succeeded(call, reference, 'REASON', timeout_s=300)
    for round_number in range(2):
        for query in queries:
            rows = answer(call, reference, 'QUERY SPARQL', query['sparql'], timeout_s=300)
            assert len(rows) == query['expected_rows'], (
                f'round {round_number}, LUBM query {query["query"]}: {len(rows)} rows')
    # A new graduate student is a Student by inference (query 6 lists all students).
    students = queries[5]
    succeeded(call, reference, 'ADD IND CLASS', f'<{DEPARTMENT}/NewGraduateStudent>',
              f'<{UB}GraduateStudent>')
    rows = answer(call, reference, 'QUERY SPARQL', students['sparql'])
    assert len(rows) == students['expected_rows'] + 1
    assert f'<{DEPARTMENT}/NewGraduateStudent>' in rows
