//! The message of a caught panic, for the error that reports it (a batch row's `Internal`
//! status, the bindings' `InternalError`).

use std::any::Any;

/// The text a panic was raised with: its payload when it is a string (`panic!` with a literal
/// or a formatted message), otherwise `"unknown panic"`.
pub fn panic_message(payload: &(dyn Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn caught(f: impl FnOnce() + std::panic::UnwindSafe) -> String {
        let hook = std::panic::take_hook();
        std::panic::set_hook(Box::new(|_| {}));
        let payload = std::panic::catch_unwind(f).unwrap_err();
        std::panic::set_hook(hook);
        panic_message(payload.as_ref())
    }

    #[test]
    fn a_literal_a_formatted_message_and_any_other_payload() {
        assert_eq!(caught(|| panic!("plain")), "plain");
        let n = 3;
        assert_eq!(caught(move || panic!("row {n} failed")), "row 3 failed");
        assert_eq!(caught(|| std::panic::panic_any(42_u8)), "unknown panic");
    }
}
