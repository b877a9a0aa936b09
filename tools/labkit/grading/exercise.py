"""One exercise: the student's files, its starter and solution files in
snippets/, its catalogue of wrong answers, and the check that grades it."""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

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
    `snippets/<solutions>/wrong/<id>/` (see :meth:`wrong_answers`)."""

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

    def wrong_answers(self) -> dict[str, dict[str, Path]]:
        """name -> {file of the exercise: the wrong version of it}.

        A file `wrong/<id>/<name>.<suffix>` replaces the exercise's file with
        that suffix (one-file exercises); a folder `wrong/<id>/<name>/` holds
        wrong versions of several files at their paths inside the package.
        """
        folder = SNIPPETS / self.solutions / 'wrong' / self.id
        answers: dict[str, dict[str, Path]] = {}
        for entry in sorted(folder.iterdir()) if folder.is_dir() else []:
            if entry.is_dir():
                answers[entry.name] = {str(f.relative_to(entry)): f
                                       for f in sorted(entry.rglob('*')) if f.is_file()}
                continue
            target = next((f for f in self.files if Path(f).name.endswith(_suffix(entry))), None)
            if target is None:
                raise ValueError(f'{entry}: no file of exercise {self.id} ends in '
                                 f'{_suffix(entry)!r} ({", ".join(self.files)})')
            answers[entry.name.removesuffix(_suffix(entry))] = {target: entry}
        return answers


def _suffix(path: Path) -> str:
    """'.launch.py' for 'x.launch.py', '.yaml' for 'x.yaml'."""
    return ''.join(path.suffixes)
