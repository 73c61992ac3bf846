//! Any bytes as the body of a studio analysis request: the server's own checks (the JSON, the
//! step, the pressure-angle limit, dragged nodes written into the text) never panic, and an
//! accepted request's text is built into a mechanism (or refused) without a panic.
#![no_main]
use camkin_cli::studio::model::Source;
use camkin_cli::studio::server::check_analysis_request;
use camkin_cli::studio::Limits;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let limits = Limits::default();
    if let Ok((text, _step, _limit)) = check_analysis_request(data, &limits) {
        let source = Source {
            name: "fuzz.toml".into(),
            folder: None,
        };
        let _ = camkin_cli::studio::model::build(&text, &source);
    }
});
