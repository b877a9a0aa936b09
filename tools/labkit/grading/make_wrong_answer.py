"""Write a wrong answer of an exercise: an edited copy of the solutions
package, as a patch against the solution (see labkit.grading.wrong_answers)::

    cp -r snippets/ch06_solutions /tmp/wrong     # then make the mistake in /tmp/wrong
    python -m labkit.grading.make_wrong_answer /tmp/wrong \\
        snippets/ch06_solutions/wrong/<exercise id>/<name>.patch \\
        --mistake 'the controller is left out' \\
        --verdict-names '/robot_controller is not in the graph'

The solution is the package the patch's wrong/ folder is in; files equal to
it are left out of the patch, and the patch is checked to apply before the
command returns.
"""
from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from pathlib import Path

from labkit.grading import wrong_answers


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog='python -m labkit.grading.make_wrong_answer',
                                     description=__doc__.split('::')[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('edited', type=Path,
                        help='a copy of snippets/<solutions>/ with the mistake made in it')
    parser.add_argument('patch', type=Path,
                        help='snippets/<solutions>/wrong/<exercise id>/<name>.patch')
    parser.add_argument('--mistake', required=True, help='which mistake it plays')
    parser.add_argument('--verdict-names', required=True, action='append',
                        help="a phrase the check's verdict must contain (may repeat)")
    args = parser.parse_args(argv)
    solutions = args.patch.parent.parent.parent
    if args.patch.suffix != '.patch' or args.patch.parent.parent.name != 'wrong' \
            or not solutions.is_dir():
        parser.error(f'{args.patch}: expected snippets/<solutions>/wrong/<exercise id>/'
                     '<name>.patch in an existing solutions package')
    if not args.edited.is_dir():
        parser.error(f'{args.edited}: not a folder (a copy of {solutions})')
    text = wrong_answers.make(solutions, args.edited, args.mistake, args.verdict_names)
    args.patch.parent.mkdir(parents=True, exist_ok=True)
    args.patch.write_text(text)
    answer = wrong_answers.read(args.patch)  # and check that it applies
    answer.apply(lambda relative: (solutions / relative).read_text())
    print(f'{args.patch}: {", ".join(f.path for f in answer.files)}')
    return 0


if __name__ == '__main__':
    sys.exit(main())
