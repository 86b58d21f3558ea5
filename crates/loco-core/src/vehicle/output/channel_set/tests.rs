//! The channel set's names, kinds and subsets.

use super::*;
use crate::vehicle::params::parameters::ParameterSet;
use std::collections::HashSet;

#[test]
fn names_are_unique_and_kinds_follow_the_probes() {
    let s = VehicleStructure::new(ParameterSet::default_vehicle()).unwrap();
    let set = ChannelSet::new(&s).unwrap();
    let names = set.names();
    assert_eq!(names.iter().collect::<HashSet<_>>().len(), names.len());
    for c in set.channels() {
        // The name suffixes the front ends used to guess the kind agree with the probe.
        let by_suffix = c.name.ends_with("_valve");
        assert_eq!(
            by_suffix,
            c.kind() == ChannelKind::DamperValve,
            "{}",
            c.name
        );
        if let Probe::DamperValve(i) = c.probe {
            assert_eq!(s.suspension.dampers[i].role, DamperRole::Yaw, "{}", c.name);
        }
    }
    let yaw = s
        .suspension
        .dampers
        .iter()
        .filter(|d| d.role == DamperRole::Yaw);
    assert_eq!(
        set.names_of_kind(ChannelKind::DamperValve).len(),
        yaw.count()
    );
    let kinds: HashSet<_> = set.channels().iter().map(Channel::kind).collect();
    assert_eq!(kinds, ChannelKind::ALL.iter().copied().collect());
    assert_eq!(set.channels()[0].unit, "m/s²");
}

#[test]
fn a_subset_keeps_the_recording_order_and_refuses_unknown_names() {
    let s = VehicleStructure::new(ParameterSet::default_vehicle()).unwrap();
    let all = ChannelSet::new(&s).unwrap().names();
    // Asked in another order than recorded: recorded in the set's order.
    let asked = [all[5].as_str(), all[1].as_str()];
    let only = ChannelSet::new(&s).unwrap().only(&asked).unwrap();
    assert_eq!(only.names(), vec![all[1].clone(), all[5].clone()]);
    assert_eq!(only.probes.len(), 2);
    let e = ChannelSet::new(&s).unwrap().only(&["no_such_channel"]);
    assert!(e.unwrap_err().to_string().contains("no_such_channel"));
}
