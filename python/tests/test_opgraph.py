"""The Python module as a user calls it (ctest PythonModule; unittest, as pytest may be absent).

Needs PYTHONPATH at the built module, OPGRAPH_SOURCE_DIR and OPGRAPH_APPLY_SEQUENCE (the C++
tool whose result the module's is compared with); python/CMakeLists.txt sets them.
"""
import json
import os
import pathlib
import subprocess
import tempfile
import unittest

import numpy as np

import opgraph

SOURCE_DIR = pathlib.Path(os.environ["OPGRAPH_SOURCE_DIR"])
APPLY_SEQUENCE = os.environ["OPGRAPH_APPLY_SEQUENCE"]
BARREL = SOURCE_DIR / "examples" / "barrel.obj"
TWISTED_VASE = SOURCE_DIR / "examples" / "twisted_vase.json"
# A short search: it ends on its work budget, at a point the work done fixes.
SHORT_SEARCH = {"work_budget": 3000, "freeform": False}


def box_cloud(count=4000, extents=(4.0, 2.0, 1.0), seed=3):
    """Points and outward normals sampled on a box's surface, area-weighted: #P by 3 each."""
    rng = np.random.default_rng(seed)
    extents = np.asarray(extents)
    areas = np.array([extents[1] * extents[2], extents[0] * extents[2], extents[0] * extents[1]])
    axes = rng.choice(3, size=count, p=areas / areas.sum())
    signs = rng.choice([-1.0, 1.0], size=count)
    points = (rng.random((count, 3)) - 0.5) * extents
    points[np.arange(count), axes] = signs * extents[axes] / 2
    normals = np.zeros((count, 3))
    normals[np.arange(count), axes] = signs
    return points + [10.0, -5.0, 2.0], normals


def obj_counts(path):
    """(vertices, faces) of an OBJ file."""
    lines = pathlib.Path(path).read_text().splitlines()
    return sum(line.startswith("v ") for line in lines), sum(line.startswith("f ") for line in lines)


def check_mesh(test, mesh):
    test.assertEqual(mesh["vertices"].dtype, np.float64)
    test.assertEqual(mesh["vertices"].ndim, 2)
    test.assertEqual(mesh["vertices"].shape[1], 3)
    test.assertGreater(len(mesh["faces"]), 0)
    for face in mesh["faces"]:
        test.assertGreaterEqual(len(face), 3)
        test.assertTrue(np.all((face >= 0) & (face < len(mesh["vertices"]))))


class ApplyTest(unittest.TestCase):
    def test_counts_match_the_cpp_tool(self):
        sequence = json.loads(TWISTED_VASE.read_text())
        mesh = opgraph.apply(sequence)
        check_mesh(self, mesh)
        with tempfile.TemporaryDirectory() as out:
            subprocess.run([APPLY_SEQUENCE, str(TWISTED_VASE), "--out", out], check=True, capture_output=True)
            self.assertEqual((len(mesh["vertices"]), len(mesh["faces"])), obj_counts(os.path.join(out, "result.obj")))

    def test_takes_json_text(self):
        cube = opgraph.apply('{"operations": []}')
        self.assertEqual(cube["vertices"].shape, (8, 3))
        self.assertEqual(len(cube["faces"]), 6)

    def test_bad_sequences_raise_value_error(self):
        with self.assertRaises(ValueError):
            opgraph.apply({"operations": [{"op": "Smooth"}]})
        with self.assertRaises(ValueError):
            opgraph.apply("{")
        with self.assertRaises(TypeError):
            opgraph.apply(42)


class RecoverTest(unittest.TestCase):
    def test_from_points_in_memory(self):
        points, normals = box_cloud()
        result = opgraph.recover(points, normals, **SHORT_SEARCH)
        check_mesh(self, result)
        self.assertEqual(result["ended_by"], "work budget")
        operations = result["sequence"]["operations"]
        self.assertEqual(len(operations), result["num_ops"])
        self.assertIn("GlobalAffineScale", [operation["op"] for operation in operations])
        # The mesh is the sequence's, in the cloud's frame (off the origin).
        np.testing.assert_array_equal(opgraph.apply(result["sequence"])["vertices"], result["vertices"])
        np.testing.assert_allclose(result["vertices"].mean(axis=0), [10, -5, 2], atol=0.5)
        # Normals are estimated when not given.
        self.assertEqual(opgraph.recover(points, **SHORT_SEARCH)["ended_by"], "work budget")

    def test_from_a_path(self):
        result = opgraph.recover(BARREL, **SHORT_SEARCH)
        check_mesh(self, result)
        self.assertEqual(opgraph.recover(str(BARREL), **SHORT_SEARCH)["sequence"], result["sequence"])
        with self.assertRaises(RuntimeError):
            opgraph.recover(SOURCE_DIR / "no_such_shape.obj")

    def test_progress_and_cancel(self):
        seen = []

        def on_progress(progress):
            seen.append(progress)
            return len(seen) < 2

        points, normals = box_cloud()
        result = opgraph.recover(points, normals, on_progress=on_progress, **SHORT_SEARCH)
        self.assertEqual(result["ended_by"], "cancelled")
        self.assertEqual(seen[0]["stage"], "search")
        self.assertGreater(seen[1]["loss"], 0)

        def fail(progress):
            raise KeyError("stop")

        with self.assertRaises(KeyError):
            opgraph.recover(points, normals, on_progress=fail, **SHORT_SEARCH)

    def test_bad_input_raises_value_error(self):
        with self.assertRaises(ValueError):
            opgraph.recover(np.zeros((10, 2)))
        points, normals = box_cloud()
        with self.assertRaises(ValueError):
            opgraph.recover(points, normals[:5])
        with self.assertRaises(ValueError):
            opgraph.recover(points, work_budget=0)


class FitTest(unittest.TestCase):
    def test_fits_a_scale(self):
        points, normals = box_cloud(extents=(4.0, 2.0, 1.0))
        start = {"operations": [{"op": "GlobalAffineScale", "params": {"scale": [1.5, 1.5, 1.5]}},
                                {"op": "GlobalAffineTranslate", "params": {"offset": [9.5, -4.5, 1.5]}}]}
        result = opgraph.fit(start, points, normals, num_samples=1000)
        self.assertLess(result["final_loss"], 0.01 * result["initial_loss"])
        np.testing.assert_allclose(result["sequence"]["operations"][0]["params"]["scale"], [2, 1, 0.5], atol=0.02)


class WriteOutputsTest(unittest.TestCase):
    def test_writes_the_files(self):
        sequence = json.loads(TWISTED_VASE.read_text())
        with tempfile.TemporaryDirectory() as out:
            opgraph.write_outputs(sequence, pathlib.Path(out) / "written", name="written")
            for name in ["result.obj", "result.glb", "rebuild_blender.py", "sequence.json", "steps/06_SimpleDeformBend.obj"]:
                self.assertGreater(os.path.getsize(os.path.join(out, "written", name)), 0, name)
            written = json.loads((pathlib.Path(out) / "written" / "sequence.json").read_text())
            self.assertEqual(written["name"], "written")
            self.assertEqual([operation["op"] for operation in written["operations"]],
                             [operation["op"] for operation in sequence["operations"]])
            opgraph.write_outputs(json.dumps(sequence), os.path.join(out, "flat"), write_steps=False)
            self.assertFalse(os.path.exists(os.path.join(out, "flat", "steps")))


if __name__ == "__main__":
    unittest.main()
