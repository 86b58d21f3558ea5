//! One output channel: its kind (what it measures, the families a front end selects channels
//! by, generated from [`channel_kind_table!`](crate::channel_kind_table)), its probe (how its
//! value is read from a state and the forces of an evaluation), its name and unit. The
//! vehicle's channels in recording order are [`super::channel_set::ChannelSet`].

use super::wheel_channels::WheelQuantity;

/// Calls `$callback! { $( CONSTANT Variant "name", "doc"; )* }` with every channel kind, in
/// declaration order: the one list from which [`ChannelKind`], its [`ChannelKind::ALL`] and
/// [`ChannelKind::name`] and the Python `ChannelKind` constants (`loco-py/src/names.rs`) are
/// generated, so a kind is added or renamed here only.
#[macro_export]
macro_rules! channel_kind_table {
    ($callback:ident) => {
        $callback! {
            ACCELERATION Acceleration "acceleration", "Acceleration of a point of the carbody or a bogie frame, m/s².";
            WHEELSET_MOTION WheelsetMotion "wheelset_motion", "Wheelset lateral displacement (m) or yaw (rad) relative to the track frame.";
            WHEEL Wheel "wheel", "A wheel-rail quantity of one wheel (force, quotient, wear number, contact angle, flange).";
            GUIDING_FORCE GuidingForce "guiding_force", "Track-plane lateral force of the rails on a wheelset ΣY, N.";
            DAMPER_FORCE DamperForce "damper_force", "Force of a damper, N.";
            DAMPER_VALVE DamperValve "damper_valve", "Frequency-valve scale factor of a yaw damper, – (0 open, 1 closed).";
            DAMPER_STROKE DamperStroke "damper_stroke", "Stroke of a damper (elongation from its static length), m.";
            ACCELEROMETER Accelerometer "accelerometer", "What an accelerometer fixed to a carbody floor point or a bogie frame reads: specific force in the body's own axes (gravity from the body's roll and the cant included), m/s².";
        }
    };
}

macro_rules! channel_kind_enum {
    ($( $constant:ident $variant:ident $name:literal, $doc:literal; )*) => {
        /// What a channel measures: the families a front end selects channels by.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum ChannelKind {
            $( #[doc = $doc] $variant, )*
        }

        impl ChannelKind {
            /// Every kind, in declaration order.
            pub const ALL: &'static [ChannelKind] = &[$( ChannelKind::$variant, )*];

            /// The kind's name as the front ends spell it.
            pub const fn name(self) -> &'static str {
                match self {
                    $( ChannelKind::$variant => $name, )*
                }
            }
        }
    };
}
crate::channel_kind_table!(channel_kind_enum);

/// How a channel's value is read.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Probe {
    /// Component `component` (0..3) of the acceleration of `point` (m, from the centre of gravity)
    /// of body `body`.
    Acceleration {
        body: usize,
        point: [f64; 3],
        component: usize,
    },
    /// Lateral displacement of wheelset `w`.
    WheelsetLateral(usize),
    /// Yaw of wheelset `w`.
    WheelsetYaw(usize),
    /// `quantity` at wheel `side` (0 left, 1 right) of wheelset `w`.
    Wheel {
        w: usize,
        side: usize,
        quantity: WheelQuantity,
    },
    /// ΣY of wheelset `w`.
    GuidingForce(usize),
    /// Force of damper `i`.
    DamperForce(usize),
    /// Valve scale factor of damper `i`.
    DamperValve(usize),
    /// Stroke of damper `i`.
    DamperStroke(usize),
    /// Component `component` of the specific force an accelerometer at `point` (m, from the
    /// centre of gravity) of body `body` reads, in the body's axes ([`crate::vehicle::output::accelerometer`]).
    Accelerometer {
        body: usize,
        point: [f64; 3],
        component: usize,
    },
}

impl Probe {
    /// The channel kind this probe records.
    pub fn kind(&self) -> ChannelKind {
        match self {
            Probe::Acceleration { .. } => ChannelKind::Acceleration,
            Probe::WheelsetLateral(_) | Probe::WheelsetYaw(_) => ChannelKind::WheelsetMotion,
            Probe::Wheel { .. } => ChannelKind::Wheel,
            Probe::GuidingForce(_) => ChannelKind::GuidingForce,
            Probe::DamperForce(_) => ChannelKind::DamperForce,
            Probe::DamperValve(_) => ChannelKind::DamperValve,
            Probe::DamperStroke(_) => ChannelKind::DamperStroke,
            Probe::Accelerometer { .. } => ChannelKind::Accelerometer,
        }
    }
}

/// One output channel.
#[derive(Debug, Clone, PartialEq)]
pub struct Channel {
    /// Name, unique in its set.
    pub name: String,
    /// SI unit (`–` for a ratio or a flag).
    pub unit: &'static str,
    /// How its value is read.
    pub probe: Probe,
}

impl Channel {
    /// What it measures.
    pub fn kind(&self) -> ChannelKind {
        self.probe.kind()
    }
}
