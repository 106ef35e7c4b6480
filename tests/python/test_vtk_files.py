"""VTK XML files for ParaView, read back with VTK's own Python readers: the points, array names and values
equal the CSV the same command writes."""

import numpy as np
import pytest

from conftest import cli, read_csv, scene_path

vtk_io = pytest.importorskip("vtkmodules.vtkIOXML")
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402


def read(reader_class, path):
    r = reader_class()
    r.SetFileName(str(path))
    r.Update()
    return r.GetOutput()


def arrays(data):
    pd = data.GetPointData()
    return {pd.GetArrayName(i): vtk_to_numpy(pd.GetArray(i)) for i in range(pd.GetNumberOfArrays())}


def assert_columns_are_the_csv(data, header, table):
    """The file's point-data arrays are the CSV's columns, in order and to the last digit."""
    a = arrays(data)
    assert list(a) == header
    for k, name in enumerate(header):
        assert np.array_equal(a[name], table[:, k])


def test_integrate_vtp_is_the_csv_as_a_polyline(tmp_path):
    args = ["integrate", scene_path("chaplygin_ball.json"), "--time", 5, "--every", 0.5, "--columns", "t,E,M1,gamma3"]
    cli(*args, "-o", tmp_path / "run.csv")
    cli(*args, "-o", tmp_path / "run.vtp")
    header, table = read_csv(tmp_path / "run.csv")
    p = read(vtk_io.vtkXMLPolyDataReader, tmp_path / "run.vtp")
    assert p.GetNumberOfPoints() == 11 and p.GetNumberOfLines() == 1 and p.GetNumberOfVerts() == 0
    assert_columns_are_the_csv(p, header, table)
    assert np.array_equal(vtk_to_numpy(p.GetPoints().GetData()), table[:, :3])


def test_poincare_vtp_is_a_point_cloud(tmp_path):
    args = ["poincare", scene_path("henon_heiles.json"), "--points", 120]
    cli(*args, "-o", tmp_path / "map.csv")
    cli(*args, "-o", tmp_path / "map.vtp")
    header, table = read_csv(tmp_path / "map.csv")
    p = read(vtk_io.vtkXMLPolyDataReader, tmp_path / "map.vtp")
    assert p.GetNumberOfPoints() == 120 and p.GetNumberOfVerts() == 120 and p.GetNumberOfLines() == 0
    assert_columns_are_the_csv(p, header, table)


def test_surface_vti_is_the_grid(tmp_path):
    args = ["surface", scene_path("henon_map.json"), "--x=-1,1", "--y=-0.5,0.5", "--step", 0.25]
    cli(*args, "-o", tmp_path / "s.csv")
    cli(*args, "-o", tmp_path / "s.vti")
    header, table = read_csv(tmp_path / "s.csv")
    img = read(vtk_io.vtkXMLImageDataReader, tmp_path / "s.vti")
    assert img.GetDimensions() == (9, 5, 1)
    assert img.GetOrigin()[:2] == (-1, -0.5) and img.GetSpacing()[:2] == (0.25, 0.25)
    values = arrays(img)["distance"]
    assert np.array_equal(values, table[:, header.index("distance")], equal_nan=True)
    # node k of the image is the CSV's row k: x fastest
    for k in (0, 7, 44):
        assert np.allclose(img.GetPoint(k)[:2], table[k, :2])


def test_sweep_vti(tmp_path):
    sweep = tmp_path / "s.json"
    sweep.write_text(
        '{"scene": "%s", "axes": [{"id": "a", "min": 1.0, "max": 1.4, "count": 3},'
        ' {"id": "b", "min": 0.2, "max": 0.3, "count": 2}], "quantity": "lyapunov.max",'
        ' "set": {"lyapunov.time": 100}}' % scene_path("henon_map.json"))
    cli("sweep", sweep, "-o", tmp_path / "s.csv", "--threads", 1)
    cli("sweep", sweep, "-o", tmp_path / "s.vti", "--threads", 1)
    import csv
    rows = list(csv.DictReader(open(tmp_path / "s.csv")))
    img = read(vtk_io.vtkXMLImageDataReader, tmp_path / "s.vti")
    assert img.GetDimensions() == (3, 2, 1)
    assert np.allclose(img.GetOrigin()[:2], (1.0, 0.2)) and np.allclose(img.GetSpacing()[:2], (0.2, 0.1))
    assert np.array_equal(arrays(img)["lyapunov.max"], [float(r["lyapunov.max"]) for r in rows])


def test_render_vtm_holds_the_views_pieces(tmp_path):
    out = tmp_path / "view.vtm"
    cli("render", scene_path("chaplygin_ball.json"), "--time", 3, "-o", out)
    assert (tmp_path / "view").is_dir()
    mb = read(vtk_io.vtkXMLMultiBlockDataReader, out)
    names = [mb.GetMetaData(i).Get(mb.NAME()) for i in range(mb.GetNumberOfBlocks())]
    assert "ball" in names and "plane" in names and "trace" in names, names
    for i in range(mb.GetNumberOfBlocks()):
        assert mb.GetBlock(i).GetNumberOfPoints() > 0
    # the trace ends under the ball: the ball's centre is R above its last point
    trace = vtk_to_numpy(mb.GetBlock(names.index("trace")).GetPoints().GetData())
    ball = vtk_to_numpy(mb.GetBlock(names.index("ball")).GetPoints().GetData())
    centre = (ball.min(axis=0) + ball.max(axis=0)) / 2
    assert np.allclose(centre[:2], trace[-1][:2], atol=0.05), (centre, trace[-1])
    # written again over itself: the pieces' folder is replaced, nothing else is touched
    cli("render", scene_path("chaplygin_ball.json"), "--time", 3, "-o", out)
    (tmp_path / "keep").mkdir()
    (tmp_path / "keep" / "mine.txt").write_text("x")
    p = cli("render", scene_path("chaplygin_ball.json"), "-o", tmp_path / "keep.vtm", check=False)
    assert p.returncode == 2 and "keep" in p.stderr and (tmp_path / "keep" / "mine.txt").exists()
    (tmp_path / "run").mkdir()  # named like the writer's pieces, but not one of them
    (tmp_path / "run" / "run_notes.txt").write_text("x")
    p = cli("render", scene_path("chaplygin_ball.json"), "-o", tmp_path / "run.vtm", check=False)
    assert p.returncode == 2 and (tmp_path / "run" / "run_notes.txt").exists() and not (tmp_path / "run.vtm").exists()
    assert not [f for f in tmp_path.iterdir() if f.name.startswith(".rollviz")]  # no temporary left
