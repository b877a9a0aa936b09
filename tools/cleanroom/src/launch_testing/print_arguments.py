"""`launch_test --show-args`: the arguments a test file's launch description declares."""
from __future__ import annotations

import launch


def print_arguments_of_launch_description(*, launch_description: launch.LaunchDescription
                                          ) -> None:
    """Print each declared argument with its description and default."""
    arguments = launch_description.get_launch_arguments()
    if not arguments:
        print('No arguments.')
        return
    print("Arguments (pass arguments as '<name>:=<value>'):")
    for argument in arguments:
        print(f"\n    '{argument.name}':")
        print(f'        {argument.description}')
        if argument.default_value is not None:
            default = ''.join(s.describe() for s in argument.default_value)
            print(f'        (default: {default})')
