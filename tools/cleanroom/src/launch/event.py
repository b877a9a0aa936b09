"""Base class of launch events."""


class Event:
    """Something that happened during a launch; handlers react to it.

    `name` identifies the event type in handler descriptions.
    """

    name = 'launch.Event'
