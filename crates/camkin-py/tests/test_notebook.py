"""The example notebook runs as a user runs it (a Jupyter kernel, by nbclient): from a motion
program to the design checks, the forces and the shop files, ending with the studio widget."""

import shutil

import nbclient
import nbformat

import camkin
from conftest import ROOT

NOTEBOOK = ROOT / "examples" / "notebooks" / "design-a-cam.ipynb"


def test_design_a_cam_notebook_runs_from_motion_to_shop_files(tmp_path):
    shutil.copy(NOTEBOOK, tmp_path / "design-a-cam.ipynb")
    nb = nbformat.read(tmp_path / "design-a-cam.ipynb", as_version=4)
    nbclient.NotebookClient(
        nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}}
    ).execute()
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    text = "".join(o.get("text", "") for o in outputs)
    assert "every design check passed" in text, text
    assert "spring from the motion:" in text and "largest contact stress:" in text
    assert "cuts the whole profile" in text
    # a figure, and the widget (anywidget installed in the tests' environment)
    kinds = [k for o in outputs for k in o.get("data", {})]
    assert "image/png" in kinds
    assert "application/vnd.jupyter.widget-view+json" in kinds
    # the shop files it wrote are the package's: the DXF is the synthesised cam's
    (shop,) = list(tmp_path.glob("cam-shop-*"))
    assert sorted(p.name for p in shop.iterdir()) == ["cam.dxf", "pitch.csv", "polar.csv"]
    mech = camkin.Mechanism.from_dict(
        {
            "length_unit": "mm",
            "cam": {
                "speed_rpm": 600.0,
                "direction": "ccw",
                "profile": {
                    "kind": "motion",
                    "base_radius": 40.0,
                    "segments": [
                        {"law": "cycloidal", "rise": 12.0, "degrees": 120},
                        {"law": "dwell", "degrees": 60},
                        {"law": "3-4-5", "rise": -12.0, "degrees": 120},
                        {"law": "dwell", "degrees": 60},
                    ],
                },
            },
            "follower": {
                "kind": "translating-roller",
                "direction": [0.0, 1.0],
                "offset": 5.0,
                "roller_radius": 10.0,
            },
        }
    )
    assert (shop / "cam.dxf").read_text() == mech.shop(tool_radius=10.0)["dxf"]
