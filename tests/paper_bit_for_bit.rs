//! `model.paper = true` is the paper's model bit for bit: every number of
//! `tests/fixtures/paper_model_main.csv` (written by `pinjoint sweep` of the main branch before
//! the complete model landed, over 100 N–1 MN × 0–500 rad/s × −35–200 °C, the rows where that
//! model answers) is reproduced to the last bit by the library with [`Params::paper`]; its
//! validity flag too, but `outside` past the model's assumptions (issue 37, docs/validity.md).

use pinjoint::{Joint, Params};

#[test]
fn the_paper_model_reproduces_the_fixture_to_the_last_bit() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/fixtures/paper_model_main.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let mut rows = 0;
    for line in lines {
        let f: Vec<&str> = line.split(',').collect();
        let num = |name: &str| -> f64 { f[header.iter().position(|h| *h == name).unwrap()].parse().unwrap() };
        let mut p = Params::paper();
        p.lubricant.temperature = num("temperature");
        let joint = Joint::new(&p).unwrap();
        let op = joint.evaluate(num("load"), num("speed")).unwrap();
        // Issue 37 item 5: past the model's assumptions (the Hertz half-width beyond the pin
        // radius, the grease above its upper service temperature) the flag is `outside`; the
        // numbers stay the paper model's, bit for bit.
        let past = num("load").abs() > joint.load_edge() || num("temperature") > p.grease.upper_service_temperature;
        let record = pinjoint::record::COLUMNS;
        for c in record.iter() {
            let Some(k) = header.iter().position(|h| *h == c.name) else { continue };
            match c.value {
                pinjoint::record::Value::Number(read) => {
                    let want: f64 = f[k].parse().unwrap();
                    assert_eq!(read(&op).to_bits(), want.to_bits(), "{} at {line}: {} against {want}", c.name, read(&op));
                }
                pinjoint::record::Value::Regime => assert_eq!(op.regime.as_str(), f[k], "{line}"),
                pinjoint::record::Value::Validity => assert_eq!(op.validity.as_str(), if past { "outside" } else { f[k] }, "{line}"),
            }
        }
        rows += 1;
    }
    assert!(rows > 1000, "{rows} rows");
}
