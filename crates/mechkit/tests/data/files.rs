//! The course's measured data files, read as they are: `baseballforce.d` (bat on ball, t [s]
//! and F [N], 100 samples, LF line endings) and `fallingtennisball02.txt` (t [s] and y [m]
//! every millisecond, CRLF line endings, leading blanks), both without a header; plus the
//! spreadsheet-style variants students make of them.

use std::fs;

use mechkit::data::{ColumnRef, DataError, Order, Separator, Table};

use crate::util::workspace;

fn example(name: &str) -> Table {
    let path = workspace().join("examples/data").join(name);
    Table::read(&path).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn baseball_force() {
    let table = example("baseballforce.d");
    assert_eq!((table.len(), table.width()), (100, 2));
    assert_eq!(table.names(), None);
    assert_eq!(table.separator(), Separator::Whitespace);
    let (t, order) = table
        .abscissa(&ColumnRef::number(1), "the impulse integral")
        .unwrap();
    assert_eq!(order, Order::Increasing);
    assert_eq!((t[0], t[99]), (0.0, 4.0e-3));
    let force = table.column(&ColumnRef::Index(1)).unwrap();
    assert_eq!((force[0], force[99]), (122.290_20, 158.098_12));
    assert_eq!(table.line_of(99), 100);
    // The trapezoidal impulse the course quotes (J ≈ 13.61 N·s; NumPy's trapezoid: 13.611668).
    let impulse: f64 = (1..t.len())
        .map(|i| 0.5 * (force[i] + force[i - 1]) * (t[i] - t[i - 1]))
        .sum();
    assert!((impulse - 13.611_668_396_820_125).abs() < 1e-9, "{impulse}");
}

#[test]
fn falling_tennis_ball_with_crlf() {
    let path = workspace().join("examples/data/fallingtennisball02.txt");
    assert!(fs::read_to_string(&path).unwrap().contains("\r\n"));
    let table = example("fallingtennisball02.txt");
    assert_eq!((table.len(), table.width()), (2500, 2));
    let (t, order) = table
        .abscissa(&ColumnRef::Index(0), "the derivative")
        .unwrap();
    assert_eq!(order, Order::Increasing);
    assert_eq!(t[0], 0.0);
    assert!((t[2499] - 2.499).abs() < 1e-9);
    let y = table.column(&ColumnRef::Index(1)).unwrap();
    assert_eq!(y[0], 1.6);
}

#[test]
fn forcedata_style_two_columns() {
    // The course's `forcedata.d`: x [m] and F [N], no header, as numpy.savetxt writes it.
    let text = "0.000000000000000000e+00 1.000000000000000000e+00\n\
                1.000000000000000056e-01 1.500000000000000000e+00\n\
                2.000000000000000111e-01 1.800000000000000044e+00\n";
    let table = Table::parse(text, "forcedata.d").unwrap();
    assert_eq!((table.len(), table.width()), (3, 2));
    assert_eq!(
        table.column(&"2".parse().unwrap()).unwrap(),
        &[1.0, 1.5, 1.8]
    );
}

#[test]
fn spreadsheet_export_with_quoted_header() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("ball.csv");
    let text = "# exported from the lab sheet\r\n\"t [s]\",\"y [m]\"\r\n0.000,1.600\r\n\
                0.001,1.599995\r\n\r\n% a pause\r\n0.002,1.599980\r\n";
    fs::write(&path, text).unwrap();
    let table = Table::read(&path).unwrap();
    assert_eq!(table.separator(), Separator::Comma);
    assert_eq!(table.names().unwrap(), ["t [s]", "y [m]"]);
    assert_eq!(
        table.column(&"y".parse().unwrap()).unwrap(),
        &[1.6, 1.599_995, 1.599_98]
    );
    assert_eq!(table.column(&"T [S]".parse().unwrap()).unwrap()[2], 0.002);
    assert_eq!((table.line_of(0), table.line_of(2)), (3, 7));
    assert_eq!(table.source(), path.display().to_string());
}

#[test]
fn missing_file_names_the_path() {
    let path = workspace().join("examples/data/no_such_file.d");
    let e = Table::read(&path).unwrap_err();
    assert!(matches!(e, DataError::Io { .. }));
    let message = e.to_string();
    assert!(message.starts_with(&format!("{}: cannot read the file: ", path.display())));
    assert!(
        message.ends_with("check the path and that it is a text file"),
        "{message}"
    );
}
