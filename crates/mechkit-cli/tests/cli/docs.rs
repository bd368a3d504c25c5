//! The command list in docs/cli.md is the one `mechkit --help` prints.

use crate::util::Dir;

#[test]
fn the_command_list_in_docs_cli_is_current() {
    let help = Dir::new().run(&["--help"]).stdout;
    let docs = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/cli.md"),
    )
    .expect("docs/cli.md");
    let block = |text: &str| -> String {
        let start = text.find("Commands:").expect("a command list");
        let end = start
            + text[start..]
                .find("Options:")
                .expect("options after the commands");
        text[start..end].to_string()
    };
    assert_eq!(
        block(&docs),
        block(&help),
        "docs/cli.md lists other commands than `mechkit --help`: copy the Commands block of the help into it"
    );
}
