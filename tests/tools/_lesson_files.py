"""Writing small lesson files for tests."""
from __future__ import annotations

import yaml

META = {
    'id': 'ch06-demo',
    'title': 'A demo lesson',
    'chapter': 6,
    'layer': 'L1',
    'duration_minutes': 15,
    'proficiency': 'B1',
    'hardware_tier': 1,
    'tier_1_path': 'Runs on a laptop.',
    'learning_objectives': ['Do a thing'],
    'skills': ['ros2 run'],
    'prerequisites': [],
}


def code_cells(*sources: str) -> str:
    return '# Demo\n\n' + '\n'.join(f'```{{code-cell}} ipython3\n{s}\n```\n' for s in sources)


def write_lesson(root, body: str, meta=None, name='demo.md'):
    front = {'kernelspec': {'name': 'python3', 'display_name': 'Python 3', 'language': 'python'},
             'textbook': meta or META}
    path = root / 'ch06' / 'L1' / name
    path.parent.mkdir(parents=True, exist_ok=True)
    if '## Key points' not in body:  # every lesson ends with one (textbook.keypoints)
        body += '\n## Key points\n\n- A demo.\n'
    path.write_text('---\n' + yaml.safe_dump(front) + '---\n\n' + body)
    return path
