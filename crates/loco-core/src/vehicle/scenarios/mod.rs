//! A scenario: wheel, rail, track, speed and run settings ([`scenario::Scenario`]), its user
//! settings resolved once, the cost bounds it must keep and the cache of its contact tables.

pub mod perfect_track;
pub mod run_limits;
pub mod scenario;
pub mod scenario_contact;
pub mod scenario_settings;
pub mod wheel_rail_cache;
