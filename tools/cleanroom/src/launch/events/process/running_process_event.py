"""Base of the events about a started process."""

from ...event import Event


class RunningProcessEvent(Event):
    """Carries what identifies a process: its action, name, command, cwd, env and pid."""

    name = 'launch.events.process.RunningProcessEvent'

    def __init__(self, *, action: object, name: str, cmd: list[str], cwd: str | None,
                 env: dict[str, str] | None, pid: int) -> None:
        self.__action = action
        self.__name = name
        self.__cmd = cmd
        self.__cwd = cwd
        self.__env = env
        self.__pid = pid

    @property
    def action(self) -> object:
        """The ExecuteProcess action that started the process."""
        return self.__action

    @property
    def execute_process_action(self) -> object:
        """Same as `action`."""
        return self.__action

    @property
    def process_name(self) -> str:
        """The process name, e.g. 'talker-1'."""
        return self.__name

    @property
    def cmd(self) -> list[str]:
        """The command line, one string per argument."""
        return self.__cmd

    @property
    def cwd(self) -> str | None:
        """The working directory, or None for the launch's."""
        return self.__cwd

    @property
    def env(self) -> dict[str, str] | None:
        """The full environment the process got."""
        return self.__env

    @property
    def pid(self) -> int:
        """The process id."""
        return self.__pid

    @property
    def process_details(self) -> dict[str, object]:
        """All of the above as a dict."""
        return {'name': self.__name, 'cmd': self.__cmd, 'cwd': self.__cwd, 'env': self.__env,
                'pid': self.__pid}
