"""The studio as a Jupyter widget: a mechanism's drawing with the angle slider and its animation,
the SVAJ, pressure-angle and curvature plots with a cursor, the design checks, the forces and a
gear pair's mesh and loads — the page ``camkin serve`` shows, computed by this package in the
kernel (no server process).

Needs ``anywidget`` (``pip install 'camkin[notebook]'``)::

    import camkin
    from camkin.widget import Studio
    w = Studio(camkin.paper_cam())
    w                       # drag a blue node: the plots follow
    w.mechanism             # the mechanism as edited, a camkin.Mechanism

The page is the studio's own (HTML, style and script of ``camkin serve``), in a frame; its
requests travel to the kernel as the widget's messages and are answered by the same library code
as the server's.
"""

from __future__ import annotations

import json
import os
from typing import Any, Optional, Union

import anywidget
import traitlets

from . import _camkin
from ._camkin import Mechanism

__all__ = ["Studio"]

# the library's bound on a mechanism file's text
_MAX_TEXT_BYTES = _camkin.MAX_TEXT_BYTES

# The frame's side of the bridge: the studio script's requests posted to the widget (the
# parent page), the kernel's answers matched back by number.
_BRIDGE = """
window.CAMKIN_BRIDGE = (function () {
  const waiting = new Map();
  let next = 0;
  window.addEventListener("message", (ev) => {
    const d = ev.data;
    if (!d || d.camkinAnswer === undefined) return;
    const done = waiting.get(d.camkinAnswer);
    if (done) { waiting.delete(d.camkinAnswer); done({ status: d.status, text: d.text }); }
  });
  return {
    name: %(name)s,
    toml: %(toml)s,
    post(what, body) {
      return new Promise((done) => {
        const id = next++;
        waiting.set(id, done);
        parent.postMessage({ camkin: id, what, body }, "*");
      });
    },
  };
})();
"""

# The widget's view: the page in a frame, its messages carried to the kernel and back. Each view
# tags its requests, so a widget shown twice answers each view its own.
_ESM = """
export default {
  render({ model, el }) {
    const frame = document.createElement("iframe");
    frame.className = "camkin-studio";
    frame.style.width = "100%";
    frame.style.border = "0";
    frame.style.height = `${model.get("height")}px`;
    frame.title = "camkin studio";
    frame.srcdoc = model.get("_page");
    const tag = Math.random().toString(36).slice(2);
    const onMessage = (ev) => {
      if (ev.source !== frame.contentWindow || !ev.data || ev.data.camkin === undefined) return;
      model.send({ id: `${tag}:${ev.data.camkin}`, what: ev.data.what, body: JSON.stringify(ev.data.body) });
    };
    window.addEventListener("message", onMessage);
    const onAnswer = (msg) => {
      if (!msg || typeof msg.id !== "string" || !msg.id.startsWith(`${tag}:`)) return;
      const id = Number(msg.id.slice(tag.length + 1));
      frame.contentWindow && frame.contentWindow.postMessage({ camkinAnswer: id, status: msg.status, text: msg.text }, "*");
    };
    model.on("msg:custom", onAnswer);
    model.on("change:height", () => { frame.style.height = `${model.get("height")}px`; });
    el.appendChild(frame);
    return () => {
      window.removeEventListener("message", onMessage);
      model.off("msg:custom", onAnswer);
    };
  },
};
"""


def _script(text: str) -> str:
    """JSON for a <script>: no ``</`` that would end it."""
    return json.dumps(text).replace("</", "<\\/")


def _studio_page(name: str, toml: str) -> str:
    html, css, js = _camkin._studio_assets()
    bridge = _BRIDGE % {"name": _script(name), "toml": _script(toml)}
    page = html.replace('<link rel="stylesheet" href="studio.css">', "<style>\n" + css + "\n</style>")
    return page.replace(
        '<script src="studio.js"></script>',
        "<script>" + bridge + "</script>\n<script>\n" + js.replace("</script", "<\\/script") + "\n</script>",
    )


class Studio(anywidget.AnyWidget):
    """The studio's view of a mechanism in a notebook, driven by the kernel.

    ``Studio(mechanism)`` takes a ``camkin.Mechanism`` (a cam-follower or a gear pair);
    ``Studio.from_toml(path_or_text)`` any mechanism file, a system's too. Drag a blue node to
    reshape a spline cam, or edit the text in the page: ``.toml`` holds the text last analysed
    and ``.mechanism`` the ``Mechanism`` it builds. ``height`` is the frame's height in CSS
    pixels.

    Example::

        w = Studio(camkin.paper_cam())
        w                                    # shown by the notebook
        w.mechanism.analyze([0.0, 90.0])     # the edited cam's numbers
    """

    _esm = _ESM
    _page = traitlets.Unicode("").tag(sync=True)
    height = traitlets.Int(1150).tag(sync=True)
    #: the mechanism's text as last analysed (dragged nodes written in)
    toml = traitlets.Unicode("").tag(sync=False)

    def __init__(
        self,
        mechanism: Optional[Mechanism] = None,
        *,
        toml: Optional[str] = None,
        name: str = "mechanism",
        base_dir: Optional[Union[str, "os.PathLike[str]"]] = None,
        height: int = 1150,
    ) -> None:
        if (mechanism is None) == (toml is None):
            raise _input("mechanism", repr(mechanism), "Studio takes a Mechanism, or toml= text (one of the two)")
        if mechanism is not None:
            if not isinstance(mechanism, Mechanism):
                raise _input(
                    "mechanism",
                    repr(mechanism),
                    f"Studio takes a camkin.Mechanism, not a {type(mechanism).__name__} "
                    "(a system: Studio.from_toml(path))",
                )
            text, name = mechanism.to_toml(), mechanism.name
            folder: Optional[str] = mechanism.base_dir
        else:
            text, folder = str(toml), os.fspath(base_dir) if base_dir is not None else None
        self._name = name
        self._folder = folder
        super().__init__(_page=_studio_page(name, text), height=height, toml=text)
        self.on_msg(self._answer)

    @classmethod
    def from_toml(cls, source: Union[str, "os.PathLike[str]"], *, height: int = 1150) -> "Studio":
        """A mechanism file (a path, or its text) in the studio: a cam, a gear pair or a system,
        in the file's own units; ``height`` in CSS pixels.

        Example::

            w = Studio.from_toml("examples/valve-train.toml")
        """
        text = os.fspath(source)
        if "\n" in text:
            return cls(toml=text, name="mechanism", height=height)
        # a path (one holding `=` too), read with the library's bound on a mechanism's text
        try:
            with open(text, encoding="utf-8-sig") as f:
                body = f.read(_MAX_TEXT_BYTES + 1)
        except (OSError, UnicodeDecodeError) as e:
            raise _input("source", text, f"cannot read mechanism file {text}: {e}") from e
        if len(body.encode("utf-8")) > _MAX_TEXT_BYTES:
            raise _input(
                "source", text, f"{text}: larger than {_MAX_TEXT_BYTES >> 20} MiB, more than a mechanism file holds"
            )
        folder = os.path.dirname(os.path.abspath(text))
        name = os.path.splitext(os.path.basename(text))[0]
        return cls(toml=body, name=name, base_dir=folder, height=height)

    def _answer(self, _widget: Any, content: Any, _buffers: Any) -> None:
        if not isinstance(content, dict) or "id" not in content:
            return
        status, text, toml = _camkin._studio_answer(
            str(content.get("what", "")), str(content.get("body", "")), self._name, self._folder
        )
        if toml is not None:
            self.toml = toml
        self.send({"id": content["id"], "status": status, "text": text})

    @property
    def mechanism(self) -> Mechanism:
        """The mechanism as last analysed in the page, built from ``.toml`` (a ``System``
        file's text is refused: read it with ``camkin.System.from_toml(w.toml)``)."""
        return _camkin._mechanism_from_text(self.toml, self._folder or ".", self._name, self._name + ".toml")


def _input(field: str, value: Optional[str], message: str) -> Exception:
    from .errors import InputError

    return InputError(message, field, value)
