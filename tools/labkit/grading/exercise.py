"""One exercise: the student's files, its starter and solution files in
snippets/, its catalogue of wrong answers, and the check that grades it."""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from labkit.grading import wrong_answers
from labkit.grading.student_package import PACKAGE, StudentPackage
from labkit.grading.verdict import Verdict
from labkit.workspace import book_snippets

#: The repository's snippets/, or a copy of it (a pip-installed labkit, see book_snippets).
SNIPPETS = book_snippets()
STARTERS = SNIPPETS / 'starters' / PACKAGE


@dataclass(repr=False)  # shown as the ✓/✗ list (Verdict._repr_pretty_), never as a repr
class ExerciseVerdict(Verdict):
    """The verdict of one exercise, knowing the exercise's files: a check's
    `requirements.files_installed(verdict, package)` reads them from here, so
    they are listed once, in the Exercise."""

    files: tuple[str, ...] = field(default=())


@dataclass(frozen=True)
class Exercise:
    """`files` are paths inside the student's package (e.g. 'launch/x.launch.py');
    the starter of each is `snippets/starters/my_ws_exercises/<file>`, the
    solution `snippets/<solutions>/<file>`, and the wrong answers live in
    `snippets/<solutions>/wrong/<id>/<name>.patch`, patches against the solution
    (see :meth:`wrong_answers` and labkit.grading.wrong_answers)."""

    id: str
    title: str
    files: tuple[str, ...]
    check: Callable[[StudentPackage, Verdict], Verdict]
    solutions: str = 'ch06_solutions'

    def grade(self, package: StudentPackage) -> Verdict:
        """Run the check on `package`; its verdict carries the exercise's title and files."""
        return self.check(package, ExerciseVerdict(self.title, files=self.files))

    def starter(self, relative: str) -> Path:
        return STARTERS / relative

    def solution(self, relative: str) -> Path:
        return SNIPPETS / self.solutions / relative

    def wrong_answer_patches(self) -> dict[str, wrong_answers.WrongAnswer]:
        """name -> the parsed patch `wrong/<id>/<name>.patch` (its Mistake and
        Verdict names lines, its diff against the solution)."""
        folder = SNIPPETS / self.solutions / 'wrong' / self.id
        patches: dict[str, wrong_answers.WrongAnswer] = {}
        for entry in sorted(folder.iterdir()) if folder.is_dir() else []:
            if entry.suffix != '.patch':
                raise ValueError(f'{entry}: a wrong answer is a <name>.patch against the solution '
                                 f'(see EXERCISES.md)')
            patches[entry.stem] = wrong_answers.read(entry)
        return patches

    def wrong_answers(self) -> dict[str, dict[str, str]]:
        """name -> {file inside the package: its text in this wrong answer}.

        A wrong answer is the solution with its patch applied: every file of
        the exercise (the solution's, or patched), and any other file the
        patch changes or creates.  A patch that no longer applies to the
        solution raises wrong_answers.PatchError naming the patch and its line.
        """
        def solution(relative: str) -> str:
            return self.solution(relative).read_text()

        return {name: {**{f: solution(f) for f in self.files}, **patch.apply(solution)}
                for name, patch in self.wrong_answer_patches().items()}
