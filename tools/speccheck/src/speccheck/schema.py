"""The JSON schema of a spec file (see docs/reference/spec-files.md).

Every mapping forbids unknown keys, so that a typo (`publisher:` for
`publishers:`) is an error rather than a requirement silently not checked.
"""
from __future__ import annotations

#: A fully qualified ROS name: /node, /ns/node, /ns/topic.
FQN_PATTERN = r'^(/[A-Za-z_][A-Za-z0-9_]*)+$'

#: Parameter types by their ROS names (rcl_interfaces/msg/ParameterType).
PARAMETER_TYPES = ['bool', 'integer', 'double', 'string', 'byte_array', 'bool_array',
                   'integer_array', 'double_array', 'string_array']

_NUMBER = {'type': 'number'}

PARAMETER = {
    'type': 'object',
    'additionalProperties': False,
    'required': ['type'],
    'properties': {
        'type': {'enum': PARAMETER_TYPES},
        'value': {},
        'min': _NUMBER,
        'max': _NUMBER,
    },
    'not': {'required': ['value', 'min']},
}

NODE = {
    'type': ['object', 'null'],
    'additionalProperties': False,
    'properties': {
        'package': {'type': 'string', 'minLength': 1},
        'executable': {'type': 'string', 'minLength': 1},
        'parameters': {
            'type': 'object',
            'propertyNames': {'pattern': r'^[A-Za-z_][A-Za-z0-9_.]*$'},
            'additionalProperties': PARAMETER,
        },
    },
}

TOPIC = {
    'type': 'object',
    'additionalProperties': False,
    'properties': {
        'type': {'type': 'string', 'pattern': r'^[A-Za-z0-9_]+/msg/[A-Za-z0-9_]+$'},
        'publishers': {'type': 'array', 'items': {'type': 'string', 'pattern': FQN_PATTERN},
                       'uniqueItems': True},
        'subscribers': {'type': 'array', 'items': {'type': 'string', 'pattern': FQN_PATTERN},
                        'uniqueItems': True},
        'rate': {
            'type': 'object',
            'additionalProperties': False,
            'minProperties': 1,
            'properties': {'min': {'type': 'number', 'minimum': 0},
                           'max': {'type': 'number', 'exclusiveMinimum': 0}},
        },
    },
}

ARGUMENT = {
    'type': ['object', 'null'],
    'additionalProperties': False,
    'properties': {
        'default': {'type': ['string', 'number', 'boolean']},
        'required': {'type': 'boolean'},
        'choices': {'type': 'array', 'items': {'type': ['string', 'number', 'boolean']},
                    'minItems': 1},
    },
    'not': {'required': ['default', 'required']},
}

SPEC_SCHEMA = {
    '$schema': 'https://json-schema.org/draft/2020-12/schema',
    'type': 'object',
    'additionalProperties': False,
    'properties': {
        'description': {'type': 'string'},
        'nodes': {'type': 'object', 'propertyNames': {'pattern': FQN_PATTERN},
                  'additionalProperties': NODE},
        'topics': {'type': 'object', 'propertyNames': {'pattern': FQN_PATTERN},
                   'additionalProperties': TOPIC},
        'arguments': {'type': 'object',
                      'propertyNames': {'pattern': r'^[A-Za-z_][A-Za-z0-9_]*$'},
                      'additionalProperties': ARGUMENT},
    },
}
