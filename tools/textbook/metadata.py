"""The lesson metadata schema, checked before anything is executed.

Metadata lives under the ``textbook:`` key of a lesson's front matter.  A
missing or malformed field fails the build with the lesson file and field.
"""
from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import jsonschema

CHAPTERS = {6: 'Building Robot Systems', 7: 'Capstone'}
LAYERS = {
    'L1': 'Manual Foundation',
    'L2': 'AI Collaboration',
    'L3': 'Intelligence Design',
    'L4': 'Spec-Driven',
}
PROFICIENCIES = ['A2', 'B1', 'C2']
HARDWARE_TIERS = {1: 'laptop only', 2: 'GPU workstation', 3: 'edge device', 4: 'physical robot'}

_TEXT = {'type': 'string', 'minLength': 1, 'pattern': r'\S'}
_TEXT_LIST = {'type': 'array', 'items': _TEXT, 'minItems': 1}

SCHEMA: dict[str, Any] = {
    'type': 'object',
    'additionalProperties': False,
    'required': ['id', 'title', 'chapter', 'layer', 'duration_minutes', 'proficiency',
                 'hardware_tier', 'tier_1_path', 'learning_objectives', 'skills',
                 'prerequisites'],
    'properties': {
        'id': {'type': 'string', 'pattern': r'^[a-z0-9][a-z0-9_-]*$'},
        'title': _TEXT,
        'chapter': {'type': 'integer', 'enum': sorted(CHAPTERS)},
        'layer': {'type': 'string', 'enum': sorted(LAYERS)},
        'duration_minutes': {'type': 'integer', 'minimum': 1, 'maximum': 600},
        'proficiency': {'type': 'string', 'enum': PROFICIENCIES},
        'hardware_tier': {'type': 'integer', 'enum': sorted(HARDWARE_TIERS)},
        'tier_1_path': _TEXT,
        'learning_objectives': _TEXT_LIST,
        'skills': _TEXT_LIST,
        'prerequisites': {'type': 'array', 'items': {'type': 'string'}, 'uniqueItems': True},
        # Domain IDs the lesson's systems use by a fixed number (6.7's sensor in
        # 101): held for the whole run, so that no other run has nodes there.
        # The lesson runs the workspace's first `colcon build` itself (6.0): its
        # folder starts with src/ only, not with the book's install copied in.
        'builds_workspace': {'type': 'boolean'},
        'fixed_domains': {'type': 'array', 'uniqueItems': True,
                          'items': {'type': 'integer', 'minimum': 90, 'maximum': 232}},
    },
}

_VALIDATOR = jsonschema.Draft202012Validator(SCHEMA)


class MetadataError(ValueError):
    """Lesson metadata is missing or malformed."""


def _field(error: jsonschema.ValidationError) -> str:
    path = list(error.absolute_path)
    if error.validator == 'required':
        path.append(re.findall(r"'([^']+)'", error.message)[0])
    return 'textbook.' + '.'.join(str(p) for p in path) if path else 'textbook'


def validate(meta: Any, source: str) -> dict[str, Any]:
    """Return ``meta`` if it follows SCHEMA, else raise naming every bad field."""
    if not isinstance(meta, dict):
        raise MetadataError(f"{source}: no 'textbook:' metadata in the front matter "
                            f"(fields: {', '.join(SCHEMA['required'])})")
    problems = sorted(_VALIDATOR.iter_errors(meta), key=lambda e: list(e.absolute_path))
    if problems:
        lines = [f"{source}: metadata field '{_field(e)}': {e.message}" for e in problems]
        raise MetadataError('\n'.join(lines))
    return meta


def check_location(meta: dict[str, Any], path: Path, source: str) -> None:
    """A lesson must sit in ``lessons/ch<chapter>/<layer>/`` matching its metadata."""
    expected = (f"ch{meta['chapter']:02d}", meta['layer'])
    actual = (path.parent.parent.name, path.parent.name)
    if actual != expected:
        raise MetadataError(f"{source}: metadata says chapter {meta['chapter']}, layer "
                            f"{meta['layer']}, so the file belongs in "
                            f"lessons/{expected[0]}/{expected[1]}/")


def check_collection(metas: dict[str, dict[str, Any]]) -> None:
    """Across lessons: unique ids, prerequisites that name existing lessons."""
    seen: dict[str, str] = {}
    problems = []
    for source, meta in metas.items():
        if meta['id'] in seen:
            problems.append(f"{source}: metadata field 'textbook.id': '{meta['id']}' is "
                            f"already used by {seen[meta['id']]}")
        seen.setdefault(meta['id'], source)
    for source, meta in metas.items():
        for prereq in meta['prerequisites']:
            if prereq not in seen:
                problems.append(f"{source}: metadata field 'textbook.prerequisites': "
                                f"'{prereq}' is not the id of any lesson")
    if problems:
        raise MetadataError('\n'.join(problems))
