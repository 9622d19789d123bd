"""How ``rbdsolve watch`` shows its state: on a terminal, rich's live display redrawn
in place (the solution of the file saved last, cut to the screen's height so that
the status and any error beneath it always show); elsewhere (a pipe, a file, a test),
each new state printed once, after the last."""

from __future__ import annotations

from rich.console import Console, Group
from rich.segment import Segment
from rich.text import Text

from rbdsolve.cli.watching import State, status_line
from rbdsolve.errors import printable

FOOTER_HINT = "watching for saves; Ctrl-C to stop"


class Screen:
    """A body over a footer, the body's first lines cut to leave the footer room on
    screen: its end, where the answers are, and the footer always show."""

    def __init__(self, body, footer) -> None:
        self.body, self.footer = body, footer

    def __rich_console__(self, console, options):
        height = options.height or console.height
        footer = console.render_lines(self.footer, options.update(height=None), pad=False)
        body = console.render_lines(self.body, options.update(height=None), pad=False)
        room = max(height - len(footer), 1)
        if len(body) > room:  # the end stays: the answers come last
            hidden = len(body) - room + 1
            note = Segment(f"… {hidden} lines above (a taller window shows them)", console.get_style("dim"))
            body = [[note]] + body[hidden:]
        for line in body + footer:
            yield from line
            yield Segment.line()


def parts(state: State):
    """The body (the solution on screen) and the footer (status, error, hint)."""
    from rbdsolve.render.terminal import render

    shown = state.files[state.latest]
    body = render(shown.report) if shown.report is not None else Text("")
    footer = [Text(status_line(w), style="dim") for w in state.files]
    if shown.error:
        footer.append(Text(printable(shown.error), style="bold red"))
    footer.append(Text(FOOTER_HINT, style="dim"))
    return body, Group(*footer)


class View:
    """A context manager whose ``show`` draws a State: live on a terminal, else printed."""

    def __init__(self, names: tuple[str, ...], console: Console | None = None) -> None:
        self.console = console or Console(highlight=False)
        self.live = None
        self.printed_rounds = 0

    def __enter__(self) -> View:
        if self.console.is_terminal:
            from rich.live import Live

            self.live = Live(console=self.console, auto_refresh=False, screen=False,
                             vertical_overflow="crop", transient=False)
            self.live.start()
        return self

    def __exit__(self, *exc) -> None:
        if self.live is not None:
            self.live.stop()

    def show(self, state: State) -> None:
        body, footer = parts(state)
        if self.live is not None:
            self.live.update(Screen(body, footer), refresh=True)
            return
        shown = state.files[state.latest]  # printed once: a new solution, or the new error alone
        self.console.print(footer if shown.error and self.printed_rounds else Group(body, footer))
        self.printed_rounds = state.rounds
