# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""LUBM data of any number of departments of University0, and the rows the 14 queries answer on it.

    python bench/lubm_generator.py DEPARTMENTS OUT.owl OUT-queries.json [--seed N]
                                   [--size full|tiny]

The Lehigh University Benchmark's own generator (UBA) is not reachable from here, so this one
follows its profile of a department, read from the UBA department in bench/data/lubm: 7-10 full,
10-14 associate and 8-11 assistant professors and 5-7 lecturers, each teaching 1-2 courses and
1-2 graduate courses; 8-14 undergraduates and 3-4 graduate students per faculty member, taking
2-4 courses and 1-3 graduate courses; an advisor (a professor) for every graduate student and
one undergraduate in five; one graduate student in five a teaching assistant, one in four a
research assistant; 10-20 research groups; publications by faculty (full professors 15-20,
associate 10-18, assistant 5-10, lecturers 0-5) with 0-2 graduate co-authors; degrees from
University0-999. The first full professor heads the department. The TBox is the univ-bench
ontology at the head of that department's file, so the output has the same form.

The expected rows are counted from what was generated, query by query, with the univ-bench
entailments each query relies on (documented at `expected_rows`): an answer that a reasoner
misses or adds shows as a count that differs. `--size tiny` writes departments of a few people,
for the benchmark's smoke run.
"""

import argparse
import json
import pathlib
import random
from typing import Dict, List

HERE = pathlib.Path(__file__).resolve().parent
DEPARTMENT0 = HERE / 'data' / 'lubm' / 'university0-department0.owl'
QUERIES = HERE / 'data' / 'lubm' / 'queries.json'
END_OF_TBOX = 'END PASTE T-box'
UNIVERSITY = 'http://www.University0.edu'
UNIVERSITIES = 1000

FACULTY_PROFILE = {  # rank -> (min, max) per department, (min, max) publications
    'full': {'FullProfessor': (7, 10), 'AssociateProfessor': (10, 14),
             'AssistantProfessor': (8, 11), 'Lecturer': (5, 7)},
    'tiny': {'FullProfessor': (1, 1), 'AssociateProfessor': (1, 1), 'AssistantProfessor': (1, 1),
             'Lecturer': (1, 1)},
}
PUBLICATIONS = {'FullProfessor': (15, 20), 'AssociateProfessor': (10, 18),
                'AssistantProfessor': (5, 10), 'Lecturer': (0, 5)}
PROFESSORS = ('FullProfessor', 'AssociateProfessor', 'AssistantProfessor')


class Department:
    """One generated department: who is who, who teaches and takes what."""

    def __init__(self, number: int, rng: random.Random, size: str):
        self.iri = f'http://www.Department{number}.University0.edu'
        self.faculty: Dict[str, str] = {}          # iri -> rank
        self.teaches: Dict[str, List[str]] = {}    # faculty iri -> course iris
        self.degrees: Dict[str, List[str]] = {}    # person iri -> university iris (any degree)
        self.undergraduates: List[str] = []
        self.graduates: List[str] = []
        self.takes: Dict[str, List[str]] = {}      # student iri -> course iris
        self.advisor: Dict[str, str] = {}          # student iri -> professor iri
        self.teaching_assistants: Dict[str, str] = {}
        self.research_assistants: List[str] = []
        self.research_groups: List[str] = []
        self.publications: Dict[str, List[str]] = {}  # publication iri -> author iris
        courses, graduate_courses = [], []
        for rank, (low, high) in FACULTY_PROFILE[size].items():
            for index in range(rng.randint(low, high)):
                member = f'{self.iri}/{rank}{index}'
                self.faculty[member] = rank
                taught = []
                for _ in range(rng.randint(1, 2)):
                    taught.append(f'{self.iri}/Course{len(courses)}')
                    courses.append(taught[-1])
                for _ in range(rng.randint(1, 2)):
                    taught.append(f'{self.iri}/GraduateCourse{len(graduate_courses)}')
                    graduate_courses.append(taught[-1])
                self.teaches[member] = taught
                self.degrees[member] = [university(rng) for _ in range(3)]
        self.head = f'{self.iri}/FullProfessor0'
        professors = [m for m, rank in self.faculty.items() if rank in PROFESSORS]
        students_per_faculty = (1, 2) if size == 'tiny' else (8, 14)
        graduates_per_faculty = (1, 1) if size == 'tiny' else (3, 4)
        for _ in self.faculty:
            for _ in range(rng.randint(*students_per_faculty)):
                student = f'{self.iri}/UndergraduateStudent{len(self.undergraduates)}'
                self.undergraduates.append(student)
                self.takes[student] = rng.sample(courses, min(len(courses), rng.randint(2, 4)))
                if rng.random() < 0.2:
                    self.advisor[student] = rng.choice(professors)
            for _ in range(rng.randint(*graduates_per_faculty)):
                student = f'{self.iri}/GraduateStudent{len(self.graduates)}'
                self.graduates.append(student)
                self.takes[student] = rng.sample(graduate_courses,
                                                 min(len(graduate_courses), rng.randint(1, 3)))
                self.advisor[student] = rng.choice(professors)
                self.degrees[student] = [university(rng)]
                if rng.random() < 0.2:
                    self.teaching_assistants[student] = rng.choice(courses)
                if rng.random() < 0.25:
                    self.research_assistants.append(student)
        groups = (1, 2) if size == 'tiny' else (10, 20)
        self.research_groups = [f'{self.iri}/ResearchGroup{i}'
                                for i in range(rng.randint(*groups))]
        for member, rank in self.faculty.items():
            for index in range(rng.randint(*PUBLICATIONS[rank])):
                coauthors = rng.sample(self.graduates, min(len(self.graduates), rng.randint(0, 2)))
                self.publications[f'{member}/Publication{index}'] = [member] + coauthors

    def rdf_xml(self) -> str:
        out = [f'<ub:Department rdf:about="{self.iri}">',
               f'   <ub:name>{name(self.iri)}</ub:name>',
               f'   <ub:subOrganizationOf rdf:resource="{UNIVERSITY}" />',
               '</ub:Department>']
        for member, rank in self.faculty.items():
            out.append(f'<ub:{rank} rdf:about="{member}">')
            out += person(member, self.iri)
            out += [f'   <ub:teacherOf rdf:resource="{c}" />' for c in self.teaches[member]]
            out += [f'   <ub:{kind}DegreeFrom rdf:resource="{u}" />' for kind, u in
                    zip(('undergraduate', 'masters', 'doctoral'), self.degrees[member])]
            out.append(f'   <ub:worksFor rdf:resource="{self.iri}" />')
            if member == self.head:
                out.append(f'   <ub:headOf rdf:resource="{self.iri}" />')
            if rank in PROFESSORS:
                out.append(f'   <ub:researchInterest>Research{len(member) % 30}'
                           '</ub:researchInterest>')
            out.append(f'</ub:{rank}>')
            for course in self.teaches[member]:
                kind = 'GraduateCourse' if '/GraduateCourse' in course else 'Course'
                out += [f'<ub:{kind} rdf:about="{course}">',
                        f'   <ub:name>{name(course)}</ub:name>', f'</ub:{kind}>']
        for student in self.undergraduates + self.graduates:
            kind = 'GraduateStudent' if student in self.degrees else 'UndergraduateStudent'
            out.append(f'<ub:{kind} rdf:about="{student}">')
            out += person(student, self.iri)
            out.append(f'   <ub:memberOf rdf:resource="{self.iri}" />')
            out += [f'   <ub:takesCourse rdf:resource="{c}" />' for c in self.takes[student]]
            if kind == 'GraduateStudent':
                out.append('   <ub:undergraduateDegreeFrom rdf:resource='
                           f'"{self.degrees[student][0]}" />')
            if student in self.advisor:
                out.append(f'   <ub:advisor rdf:resource="{self.advisor[student]}" />')
            out.append(f'</ub:{kind}>')
        for student, course in self.teaching_assistants.items():
            out += [f'<ub:TeachingAssistant rdf:about="{student}">',
                    f'   <ub:teachingAssistantOf rdf:resource="{course}" />',
                    '</ub:TeachingAssistant>']
        out += [f'<ub:ResearchAssistant rdf:about="{s}" />' for s in self.research_assistants]
        for group in self.research_groups:
            out += [f'<ub:ResearchGroup rdf:about="{group}">',
                    f'   <ub:subOrganizationOf rdf:resource="{self.iri}" />',
                    '</ub:ResearchGroup>']
        for publication, authors in self.publications.items():
            out += [f'<ub:Publication rdf:about="{publication}">',
                    f'   <ub:name>{name(publication)}</ub:name>']
            out += [f'   <ub:publicationAuthor rdf:resource="{a}" />' for a in authors]
            out.append('</ub:Publication>')
        return '\n'.join(out)


def university(rng: random.Random) -> str:
    return f'http://www.University{rng.randrange(UNIVERSITIES)}.edu'


def name(iri: str) -> str:
    return iri.rsplit('/', 1)[-1].split('.')[0]


def person(iri: str, department: str) -> List[str]:
    return [f'   <ub:name>{name(iri)}</ub:name>',
            f'   <ub:emailAddress>{name(iri)}@{department[len("http://www."):]}</ub:emailAddress>',
            '   <ub:telephone>xxx-xxx-xxxx</ub:telephone>']


def expected_rows(departments: List[Department]) -> Dict[int, int]:
    """Rows of each query, counted from the data with the entailments the query relies on.

    Students: undergraduates, and graduate students (Person and takesCourse some
    GraduateCourse, a Course); persons: students and faculty; memberOf includes worksFor;
    subOrganizationOf is transitive; hasAlumnus is the inverse of the degrees.
    """
    first = departments[0]
    students = [s for d in departments for s in d.undergraduates + d.graduates]
    takes = {s: c for d in departments for s, c in d.takes.items()}
    advisor = {s: a for d in departments for s, a in d.advisor.items()}
    teaches = {f: c for d in departments for f, c in d.teaches.items()}
    graduate_course0 = f'{first.iri}/GraduateCourse0'
    taking_gc0 = sum(graduate_course0 in takes[s] for s in first.graduates)
    associate0 = f'{first.iri}/AssociateProfessor0'
    return {
        1: taking_gc0,
        2: sum(d.degrees[s][0] == UNIVERSITY for d in departments for s in d.graduates),
        3: sum(f'{first.iri}/AssistantProfessor0' in authors
               for authors in first.publications.values()),
        4: sum(rank in PROFESSORS for rank in first.faculty.values()),
        5: len(first.undergraduates) + len(first.graduates) + len(first.faculty),
        6: len(students),
        7: sum(course in takes[s] for s in students for course in teaches.get(associate0, [])),
        8: len(students),
        9: sum(course in teaches[advisor[s]]
               for s in students if s in advisor for course in takes[s]),
        10: taking_gc0,
        11: sum(len(d.research_groups) for d in departments),
        12: len(departments),
        13: sum(UNIVERSITY in degrees for d in departments for degrees in d.degrees.values()),
        14: sum(len(d.undergraduates) for d in departments),
    }


def generate(count: int, ontology: pathlib.Path, queries: pathlib.Path, seed: int = 0,
             size: str = 'full') -> Dict[str, int]:
    """Writes the ontology and the queries with their expected rows; returns a few sizes."""
    rng = random.Random(seed)
    departments = [Department(number, rng, size) for number in range(count)]
    text = DEPARTMENT0.read_text()
    tbox = text[:text.index('\n', text.index(END_OF_TBOX))]
    with ontology.open('w') as out:
        out.write(tbox + '\n\n')
        out.write(f'<ub:University rdf:about="{UNIVERSITY}">\n   <ub:name>University0</ub:name>\n'
                  '</ub:University>\n')
        for department in departments:
            out.write(department.rdf_xml() + '\n')
        out.write('</rdf:RDF>\n')
    rows = expected_rows(departments)
    adapted = [{**query, 'expected_rows': rows[query['query']]}
               for query in json.loads(QUERIES.read_text())]
    queries.write_text(json.dumps(adapted, indent=1) + '\n')
    people = sum(len(d.faculty) + len(d.undergraduates) + len(d.graduates) for d in departments)
    return {'departments': count, 'people': people,
            'publications': sum(len(d.publications) for d in departments)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('departments', type=int)
    parser.add_argument('ontology', type=pathlib.Path)
    parser.add_argument('queries', type=pathlib.Path)
    parser.add_argument('--seed', type=int, default=0)
    parser.add_argument('--size', choices=sorted(FACULTY_PROFILE), default='full')
    options = parser.parse_args()
    print(generate(options.departments, options.ontology, options.queries, options.seed,
                   options.size))


if __name__ == '__main__':
    main()
