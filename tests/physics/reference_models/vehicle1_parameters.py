"""The Manchester benchmark's Vehicle 1 (passenger coach) for the linear lateral model, SI.

Source: ``shared/data/manchester_vehicle1/README.md`` (S. Iwnicki, "Manchester Benchmarks for
Rail Vehicle Simulation", Vehicle System Dynamics 30 (1998) 295-313, read from two public code
files, A and B, that follow it). Its one disagreement: the primary vertical stiffness per axle
box is 1220 kN/m in B and 1200 kN/m in A; B's value is used (B is the full 3-D set, A a 2-D
pitch-plane subset). In the lateral model it only enters the bogie frame's roll.

What the README does not give, and is chosen here:
- contact semi-distance l0 = 0.75 m: the nominal 1500 mm between the rolling circles that
  EN 15302 uses for standard gauge (the README gives the back-to-back, 1.360 m, not l0);
- wheel and rail transverse radii for Hertz: a coned tread (transverse radius infinite) on the
  UIC60 rail's 300 mm crown radius (EN 13674-1; the profiles are not known), rail straight
  along the track, so A = 1/(2 r0) and B = 1/(2·0.3) 1/m; steel as in ``contact_coefficients``;
- the static wheel load from the total mass, 44 482 kg × 9.81 / 8 (the README's 54.5 kN);
- conicity: the profiles are unknown, so 0.05, 0.1, 0.2 and 0.3 are the test cases;
- the "anti-bending" bogie-to-body rotation stiffness (10.5 kN·m/rad) is read as a yaw
  stiffness between each bogie and the car body, one per bogie (the README lists it among the
  per-side values without saying about which axis; as one per bogie it is 3 % of the yaw
  stiffness the longitudinal secondary springs give, 2 × 160 kN/m × (1 m)²);
- the lateral bump stops have a 25 mm free gap, so they do not act in the linear model;
- no yaw dampers and no traction rods (the sources give none);
- the wheelsets' gravitational stiffness is zero (coned wheels; unknown profiles) and the
  wheelset roll is not a coordinate (it follows y through the contact and is neglected).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from .contact_coefficients import CreepCoefficients, Ellipse, creep_coefficients

#: Gravitational acceleration, m/s².
G = 9.81


@dataclass(frozen=True)
class Body:
    """A rigid body: mass (kg), roll and yaw inertia (kg·m²), centre of gravity height above
    the rail (m)."""

    mass: float
    roll_inertia: float
    yaw_inertia: float
    height: float


@dataclass(frozen=True)
class Element:
    """Stiffness (N/m) and damping (N·s/m) of one suspension element in one direction."""

    stiffness: float
    damping: float = 0.0


@dataclass(frozen=True)
class Vehicle1:
    """Vehicle 1's parameters, SI; the defaults are the README's (per axle box for the primary,
    per bogie side for the secondary), with the choices listed in this module's docstring."""

    carbody: Body = Body(32000.0, 56800.0, 1970000.0, 1.80)
    bogie: Body = Body(2615.0, 1722.0, 3067.0, 0.60)
    wheelset: Body = Body(1813.0, 1120.0, 1120.0, 0.46)
    bogie_semi_distance: float = 9.50
    wheelbase_semi: float = 1.28
    rolling_radius: float = 0.46
    contact_semi_distance: float = 0.75
    primary_semi_spacing: float = 1.0
    secondary_semi_spacing: float = 1.0
    primary_height: float = 0.46
    secondary_height: float = 0.8275
    primary_lateral: Element = Element(3.884e6, 2.0e3)
    primary_longitudinal: Element = Element(31.391e6, 15.0e3)
    primary_vertical: Element = Element(1.220e6, 4.0e3)
    secondary_lateral: Element = Element(160.0e3, 32.0e3)
    secondary_longitudinal: Element = Element(160.0e3, 0.0)
    secondary_vertical: Element = Element(430.0e3, 20.0e3)
    anti_roll_per_bogie: float = 940.0e3
    anti_bending_per_bogie: float = 10.5e3
    rail_crown_radius: float = 0.300
    #: Gravity's roll terms of the preloaded vertical springs (a body on springs below its
    #: centre of gravity loses W·h of roll stiffness).
    gravity: bool = True
    #: Spin creep (f23) in the wheelset forces; off in the table (textbook's simplest model).
    spin: bool = False
    gravitational_stiffness: float = 0.0
    #: Creep coefficients to use instead of Hertz and Kalker's (for checks with f11 = f22).
    creep_override: CreepCoefficients | None = None

    @property
    def total_mass(self) -> float:
        """kg."""
        return self.carbody.mass + 2 * self.bogie.mass + 4 * self.wheelset.mass

    @property
    def wheel_load(self) -> float:
        """Static vertical load of one wheel, N."""
        return self.total_mass * G / 8.0

    def creep(self) -> CreepCoefficients:
        """Kalker's coefficients of one contact at the static wheel load."""
        if self.creep_override is not None:
            return self.creep_override
        return creep_coefficients(
            self.wheel_load, 1.0 / (2.0 * self.rolling_radius), 1.0 / (2.0 * self.rail_crown_radius)
        )

    def with_contact(
        self,
        f11: float,
        f22: float,
        f23: float = 0.0,
        gravitational_stiffness: float = 0.0,
        contact_semi_distance: float | None = None,
        rolling_radius: float | None = None,
    ) -> Vehicle1:
        """The vehicle with given linear contact parameters (per contact f11, f22 in N, f23 in
        N·m; per wheelset k_g in N/m; l0, r0 in m), e.g. those another model's contact gives,
        in place of the Hertz and Kalker ones."""
        return replace(
            self,
            creep_override=CreepCoefficients(f11, f22, f23, Ellipse(float("nan"), float("nan"))),
            gravitational_stiffness=gravitational_stiffness,
            contact_semi_distance=contact_semi_distance or self.contact_semi_distance,
            rolling_radius=rolling_radius or self.rolling_radius,
        )


#: The conicities taken as the test cases (the profiles are unknown), –.
CONICITIES = (0.05, 0.1, 0.2, 0.3)
