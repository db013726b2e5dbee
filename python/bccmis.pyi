"""bccmis: adaptive BCC lattices and tetrahedral meshes by isosurface stuffing.

Type stubs of the compiled module (spec/python.md).
"""
from typing import Any, Callable, Literal, Optional, Sequence, Tuple, TypedDict, Union, type_check_only

from typing_extensions import Unpack

import numpy as np
import numpy.typing as npt

Impl = Literal["fast", "reference"]
Point = Sequence[int]
BoundsLike = Sequence[Sequence[float]]

class CheckError(RuntimeError):
    """check=True found a problem in the mesh (spec/python.md P6)."""

class InvariantError(RuntimeError):
    """Lattice.check() found a violated invariant: code, positions, section."""
    code: str
    positions: npt.NDArray[np.int64]
    section: str

class Shape:
    """A closed shape the mesher can mesh. bccmis.shapes.sphere(r=1)"""
    @property
    def description(self) -> str: ...
    @property
    def volume(self) -> float: ...
    @property
    def bounds(self) -> Tuple[Tuple[float, float, float], Tuple[float, float, float]]: ...

class shapes:
    """The built-in shapes (spec/stuffing.md S1)."""
    @staticmethod
    def sphere(r: float = 1.0) -> Shape:
        """A sphere of radius r at the origin. bccmis.shapes.sphere(r=2)"""
    @staticmethod
    def torus(R: float = 1.0, r: float = 0.4) -> Shape:
        """A torus around the z axis. bccmis.shapes.torus(R=1, r=0.3)"""
    @staticmethod
    def spheres(r: float = 0.7, d: float = 1.0) -> Shape:
        """Two spheres at x = -d/2 and d/2, united. bccmis.shapes.spheres(r=0.7, d=1)"""
    @staticmethod
    def builtin(spec: str) -> Shape:
        """A built-in shape by the CLI's --shape text. bccmis.shapes.builtin('torus:R=1,r=0.4')"""

class TetMesh:
    """A tetrahedral mesh made by bccmis.stuff (spec/python.md P4)."""
    @property
    def points(self) -> npt.NDArray[np.float64]:
        """float64 (n, 3), a read-only view. mesh.points[:3]"""
    @property
    def tets(self) -> npt.NDArray[np.uint32]:
        """uint32 (m, 4), positively oriented. mesh.tets.shape"""
    @property
    def levels(self) -> npt.NDArray[np.int32]:
        """int32 (m,): each tetrahedron's lattice level. mesh.levels.max()"""
    @property
    def kinds(self) -> npt.NDArray[np.uint8]:
        """uint8 (n,): 0 lattice vertex, 1 warped, 2 cut point. (mesh.kinds == 2).sum()"""
    @property
    def boundary_faces(self) -> npt.NDArray[np.uint32]:
        """uint32 (b, 3): the boundary triangles, outward. mesh.boundary_faces.shape"""
    @property
    def stats(self) -> Optional[dict]:
        """With stats=True: bccmis stuff --json's object. mesh.stats['tetrahedra']"""
    @property
    def shape(self) -> str:
        """The shape's description. mesh.shape"""
    def dihedral_angles(self) -> npt.NDArray[np.float64]:
        """float64 (m, 6), degrees. mesh.dihedral_angles().min()"""
    def write(self, path: str, binary: bool = False, compress: bool = False) -> None:
        """Writes .vtu, .msh, .mesh (tetrahedra), .off or .obj (boundary); compress: a zlib-compressed .vtu. mesh.write('out.vtu', compress=True)"""
    def to_meshio(self) -> Any:
        """A meshio.Mesh: tetra cells, point data kind, cell data level. mesh.to_meshio().write('out.vtk')"""
    def __len__(self) -> int: ...

@type_check_only
class _RunOptions(TypedDict, total=False):
    """The keywords of stuff and stuff_file: the CLI's options of the same names (spec/python.md P1)."""
    max_level: int  # 4
    min_level: int  # 0
    cells: int  # 4
    size: Optional[float]
    impl: Impl  # "fast"
    check: bool
    strict: bool
    stats: bool
    features: Optional[bool]  # None: on for a triangle mesh
    feature_angle: Optional[float]  # 60
    progress: Optional[Callable[[str], None]]

def stuff(
    shape: Union[npt.ArrayLike, Shape, Callable[[npt.NDArray[np.float64]], npt.ArrayLike]],
    faces: Optional[npt.ArrayLike] = None,
    *,
    bounds: Optional[BoundsLike] = None,
    **options: Unpack[_RunOptions],
) -> TetMesh:
    """A tetrahedral mesh of (vertices, faces), a Shape or a callable. mesh = bccmis.stuff(bccmis.shapes.torus(), max_level=3)"""

def stuff_file(
    path: str, *, format: Optional[Literal["off", "obj", "ply", "stl"]] = None, **options: Unpack[_RunOptions]
) -> TetMesh:
    """A tetrahedral mesh of a triangle mesh file. mesh = bccmis.stuff_file('bunny.off', max_level=5)"""

class MovingShape:
    """A shape moving through one lattice, its mesh updated locally. m = bccmis.MovingShape(bccmis.shapes.sphere(), (1, 0, 0))"""
    def __init__(
        self,
        shape: Union[npt.ArrayLike, Shape, Callable[[npt.NDArray[np.float64]], npt.ArrayLike]],
        path: Optional[Sequence[float]] = None,
        faces: Optional[npt.ArrayLike] = None,
        *,
        max_level: int = 4,
        min_level: int = 0,
        cells: int = 4,
        bounds: Optional[BoundsLike] = None,
    ) -> None: ...
    @property
    def mesh(self) -> TetMesh:
        """The mesh where the shape is now. m.mesh"""
    def move(self, offset: Sequence[float]) -> Tuple[TetMesh, dict]:
        """Moves the shape to offset: (the new mesh, what changed). mesh, report = m.move((0.5, 0, 0))"""

@type_check_only
class _AdaptiveLattice:
    """What Lattice and Lattice3 both offer; a point is 2 or 3 integers."""
    @property
    def impl(self) -> Impl: ...
    def refine(self, c: Point) -> Optional[str]:
        """None when applied, else the refusal code. l.refine((4, 4))"""
    def coarsen(self, n: Point) -> Optional[str]:
        """None when applied, else the refusal code. l.coarsen((4, 4))"""
    def can_refine(self, c: Point) -> Optional[str]:
        """The refusal code refine(c) would give, or None. l.can_refine((4, 4))"""
    def can_coarsen(self, n: Point) -> Optional[str]:
        """The refusal code coarsen(n) would give, or None. l.can_coarsen((4, 4))"""
    def cells(self) -> npt.NDArray[np.int64]:
        """The cell centers, sorted: int64 (k, 2 or 3). l.cells()"""
    def nodes(self) -> npt.NDArray[np.int64]:
        """The nodes, sorted: int64 (k, 2 or 3). l.nodes()"""
    def levels(self) -> npt.NDArray[np.int32]:
        """The level of each of cells(). l.levels()"""
    def neighbors(self, v: Point) -> npt.NDArray[np.int64]:
        """N(v), sorted: int64 (k, 2 or 3). l.neighbors((0, 0))"""
    def canonical_state(self) -> str:
        """The canonical state (spec/formats.md). print(l.canonical_state())"""
    def check(self) -> None:
        """Raises InvariantError when an invariant is violated. l.check()"""

class Lattice(_AdaptiveLattice):
    """A 2D adaptive BCC lattice (spec/formats.md). bccmis.Lattice(2, 2, 3)"""
    def __init__(self, W: int, H: int, L: int, impl: Impl = "reference") -> None: ...

class Lattice3(_AdaptiveLattice):
    """A 3D adaptive BCC lattice (spec/lattice3d.md). bccmis.Lattice3(1, 1, 1, 2)"""
    def __init__(self, W: int, H: int, D: int, L: int, impl: Impl = "reference") -> None: ...
    def tetrahedra(self) -> npt.NDArray[np.int64]:
        """The graded mesh's tetrahedra by vertex position: int64 (t, 4, 3). l.tetrahedra().shape"""

def replay(trace: str, impl: Impl = "reference") -> Tuple[Union[Lattice, Lattice3], str]:
    """Replays a trace: (the final lattice, the decision log). g, log = bccmis.replay(open('fig2.trace').read())"""

def parse_state(text: str) -> Union[Lattice, Lattice3]:
    """A canonical state as a reference lattice, unchecked. g = bccmis.parse_state(open('run.state').read())"""
