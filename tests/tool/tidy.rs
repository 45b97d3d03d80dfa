//! The repository's own rules, as tests: sizes (no function over 100 lines,
//! no source file over 700, the command line within its budget, the READMEs
//! within theirs), and documentation that names only paths that exist.
//! Functions are found by `syn` (its spans give their lines), not by a
//! scanner of our own.

use std::path::{Path, PathBuf};
use syn::spanned::Spanned;
use syn::visit::Visit;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// Most lines of one function, from `fn` to its closing brace.
const MAX_FN_LINES: usize = 100;
/// Most lines of one source file (Rust, Python or shell).
const MAX_FILE_LINES: usize = 700;
/// Most lines of the command line (`src/cli` and `src/main.rs`, as `wc -l`
/// counts them, unit tests included). The budget is the tool as it is: its
/// readers keep README's promises (two passes with hashed chunks, constant
/// memory, CSV line numbers as an editor counts them, stdin spooled) within
/// the row budgets of `fricosc bench`, and it serves the system and fit
/// interfaces (validate's system columns and diverged values, a history's
/// body columns, fit's values rounded to their errors, unknown columns
/// refused, the rig's system), and the plane (`--transverse-amp` and
/// `--transverse-phase` for `point` and `table`, the plane's output columns,
/// its stepper, its two figures and its bench cases, flat and curved).
/// Growing it is a decision for a commit of its own.
const MAX_CLI_LINES: usize = 9_100;

/// The files under `dir` (recursively) whose names end in one of `exts`,
/// build outputs left out.
fn files(dir: &Path, exts: &[&str]) -> Vec<PathBuf> {
    let mut out = vec![];
    let Ok(entries) = std::fs::read_dir(dir) else { return out };
    for e in entries.flatten() {
        let p = e.path();
        let name = e.file_name().to_string_lossy().into_owned();
        if p.is_dir() {
            if name != "target" && !name.starts_with('.') {
                out.extend(files(&p, exts));
            }
        } else if exts.iter().any(|x| name.ends_with(x)) {
            out.push(p);
        }
    }
    out
}

/// `p` from the repository's root, for messages.
fn shown(p: &Path) -> String {
    p.strip_prefix(ROOT).unwrap_or(p).display().to_string()
}

fn lines(p: &Path) -> usize {
    std::fs::read_to_string(p).unwrap().lines().count()
}

/// The functions of a file longer than [`MAX_FN_LINES`]: `(name, first line, lines)`.
#[derive(Default)]
struct LongFns(Vec<(String, usize, usize)>);

impl LongFns {
    fn check(&mut self, name: &syn::Ident, first: proc_macro2::Span, last: proc_macro2::Span) {
        let (a, b) = (first.start().line, last.end().line);
        if b + 1 - a > MAX_FN_LINES {
            self.0.push((name.to_string(), a, b + 1 - a));
        }
    }
}

impl<'a> Visit<'a> for LongFns {
    fn visit_item_fn(&mut self, f: &'a syn::ItemFn) {
        self.check(&f.sig.ident, f.sig.fn_token.span(), f.block.span());
        syn::visit::visit_item_fn(self, f);
    }
    fn visit_impl_item_fn(&mut self, f: &'a syn::ImplItemFn) {
        self.check(&f.sig.ident, f.sig.fn_token.span(), f.block.span());
        syn::visit::visit_impl_item_fn(self, f);
    }
    fn visit_trait_item_fn(&mut self, f: &'a syn::TraitItemFn) {
        if let Some(body) = &f.default {
            self.check(&f.sig.ident, f.sig.fn_token.span(), body.span());
        }
        syn::visit::visit_trait_item_fn(self, f);
    }
}

#[test]
fn no_function_is_over_100_lines() {
    let mut long = vec![];
    let mut seen = 0;
    for dir in ["src", "tests"] {
        for p in files(&Path::new(ROOT).join(dir), &[".rs"]) {
            let file =
                syn::parse_file(&std::fs::read_to_string(&p).unwrap()).unwrap_or_else(|e| panic!("{}: {e}", shown(&p)));
            let mut v = LongFns::default();
            v.visit_file(&file);
            long.extend(v.0.into_iter().map(|(n, at, len)| format!("{}:{at} {n}: {len} lines", shown(&p))));
            seen += 1;
        }
    }
    assert!(seen > 100, "only {seen} Rust files found under {ROOT}");
    assert!(long.is_empty(), "functions over {MAX_FN_LINES} lines:\n{}", long.join("\n"));
}

/// The checker finds long functions, in an impl and in a module, and passes
/// a short one (a function of exactly 100 lines is allowed).
#[test]
fn the_function_check_sees_long_functions() {
    let body = "    let x = 1;\n".repeat(MAX_FN_LINES - 1);
    let allowed = "    let x = 1;\n".repeat(MAX_FN_LINES - 2);
    let src = format!(
        "impl A {{\n    fn long() {{\n{body}    }}\n}}\nfn short() {{\n{allowed}}}\nmod m {{\n    fn inner() {{\n{body}}}\n}}\n"
    );
    let mut v = LongFns::default();
    v.visit_file(&syn::parse_file(&src).unwrap());
    let found: Vec<_> = v.0.iter().map(|(n, _, len)| (n.as_str(), *len)).collect();
    assert_eq!(found, [("long", MAX_FN_LINES + 1), ("inner", MAX_FN_LINES + 1)]);
}

#[test]
fn no_source_file_is_over_700_lines() {
    let long: Vec<String> = ["src", "tests", "data"]
        .iter()
        .flat_map(|d| files(&Path::new(ROOT).join(d), &[".rs", ".py", ".sh"]))
        .map(|p| (lines(&p), p))
        .filter(|(n, _)| *n > MAX_FILE_LINES)
        .map(|(n, p)| format!("{}: {n} lines", shown(&p)))
        .collect();
    assert!(long.is_empty(), "files over {MAX_FILE_LINES} lines:\n{}", long.join("\n"));
}

#[test]
fn the_command_line_is_within_its_budget() {
    let root = Path::new(ROOT);
    let cli: usize = files(&root.join("src/cli"), &[".rs"]).iter().map(|p| lines(p)).sum::<usize>()
        + lines(&root.join("src/main.rs"));
    assert!(cli > 1000, "{cli} lines: the command line was not found");
    assert!(cli <= MAX_CLI_LINES, "the command line has {cli} lines, over its budget of {MAX_CLI_LINES}");
}

#[test]
fn the_readmes_are_within_their_budgets() {
    for (doc, max) in [("README.md", 400), ("src/README.md", 200), ("tests/README.md", 200)] {
        let n = lines(&Path::new(ROOT).join(doc));
        assert!(n <= max, "{doc}: {n} lines, over {max}");
    }
}

/// The repository paths a Markdown text names (in backticks or as a link
/// target), where they start at a top-level folder; patterns (`*`, `{..}`,
/// `<..>`, `...`) are not paths, and a `#fragment` or `:line` is cut off.
fn named_paths(text: &str) -> Vec<String> {
    let mut out = vec![];
    let ticks = text.split('`').skip(1).step_by(2);
    let links = text.split("](").skip(1).filter_map(|s| s.split(')').next());
    for t in ticks.chain(links) {
        let t = t.split('#').next().unwrap_or("");
        let t = t.split(':').next().unwrap_or("");
        let top = ["src/", "tests/", "data/", ".ci/"].iter().any(|d| t.starts_with(d));
        let pattern = t.contains(['*', '{', '<', ' ']) || t.contains("...");
        if top && !pattern {
            out.push(t.to_string());
        }
    }
    out
}

#[test]
fn every_path_a_readme_names_exists() {
    let root = Path::new(ROOT);
    let mut docs: Vec<PathBuf> =
        ["README.md", "src/README.md", "tests/README.md", "data/README.md"].iter().map(|d| root.join(d)).collect();
    docs.extend(files(&root.join("src/python"), &["README.md"]));
    let mut missing = vec![];
    let mut named = 0;
    for doc in &docs {
        for p in named_paths(&std::fs::read_to_string(doc).unwrap()) {
            named += 1;
            if !root.join(&p).exists() {
                missing.push(format!("{}: {p}", shown(doc)));
            }
        }
    }
    assert!(named > 50, "only {named} paths named: the scan is broken");
    assert!(missing.is_empty(), "paths named but not in the repository:\n{}", missing.join("\n"));
}

/// The scan takes backticked and linked paths, cuts fragments and line
/// numbers, and passes over patterns and other code.
#[test]
fn the_path_scan_takes_paths_only() {
    let text = "See `src/cli/`, [x](data/bench/a.svg#top), `tests/tool/cli.rs:12`, `src/**/x.rs`, \
                `data/{a,b}`, `cargo test`, `src/<name>.rs`, (not/a/link)";
    assert_eq!(named_paths(text), ["src/cli/", "tests/tool/cli.rs", "data/bench/a.svg"]);
}
