//! The library's files import one another without cycles (ARCHITECTURE.md): each file of
//! `src/` but the command line's is a node, each module it names by a `crate::`, `super::` or
//! `self::` path, or by a child module's name in a `use`, an edge; a file's own ancestors are
//! not counted (a child reads its parent's items), nor are its tests.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

type Module = Vec<String>;

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("a source folder") {
        let path = entry.expect("an entry").path();
        if path.is_dir() {
            if path.file_name().is_some_and(|n| n != "bin") {
                rust_files(&path, out);
            }
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// `src/a/b.rs` and `src/a/b/mod.rs` are `a::b`; `src/lib.rs` is the crate.
fn module_of(src: &Path, file: &Path) -> Module {
    let relative = file
        .strip_prefix(src)
        .expect("under src")
        .with_extension("");
    let mut parts: Module = relative
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    if parts.last().is_some_and(|p| p == "mod" || p == "lib") {
        parts.pop();
    }
    parts
}

/// The code of a file without its comments (doc links name modules without importing them)
/// and without its test module (the last item of a file that has one).
fn code_of(text: &str) -> String {
    let text = text.split("\n#[cfg(test)]").next().unwrap_or("");
    text.lines()
        .map(|line| match line.find("//") {
            Some(i) => &line[..i],
            None => line,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The paths a `use` tree names, its braces expanded: `a::{b::C, d}` is `a::b::C` and `a::d`.
fn expand_use(tree: &str, prefix: &str, out: &mut Vec<String>) {
    let tree = tree.trim();
    let Some(open) = tree.find('{') else {
        let path = tree.split(" as ").next().unwrap_or("").trim();
        if !path.is_empty() {
            out.push(format!("{prefix}{path}"));
        }
        return;
    };
    // Not a `use` tree (the words "use {" in a string): nothing to expand.
    let Some(close) = tree.rfind('}').filter(|&close| close > open) else {
        return;
    };
    let inner = &tree[open + 1..close];
    let prefix = format!("{prefix}{}", &tree[..open]);
    let (mut depth, mut start) = (0, 0);
    for (i, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                expand_use(&inner[start..i], &prefix, out);
                start = i + 1;
            }
            _ => {}
        }
    }
    expand_use(&inner[start..], &prefix, out);
}

/// Every path in `code` that starts at `crate`, `super` or `self`, and every path of its `use`
/// declarations.
fn paths_in(code: &str) -> Vec<String> {
    let mut paths = Vec::new();
    let mut rest = code;
    while let Some(at) = rest.find("use ") {
        let before = rest[..at].chars().last();
        let tail = &rest[at + 4..];
        let end = tail.find(';').unwrap_or(tail.len());
        if before.is_none_or(|c| !c.is_alphanumeric() && c != '_') {
            expand_use(&tail[..end], "", &mut paths);
        }
        rest = &tail[end.min(tail.len())..];
    }
    let bytes = code.as_bytes();
    for start in ["crate::", "super::", "self::"] {
        for (i, _) in code.match_indices(start) {
            if i > 0 && (bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_') {
                continue;
            }
            let end = code[i..]
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .map_or(code.len(), |n| i + n);
            paths.push(code[i..end].to_string());
        }
    }
    paths
}

/// The module a path inside `from` names: the longest prefix of it that is a module.
fn resolve(from: &Module, path: &str, modules: &BTreeSet<Module>) -> Option<Module> {
    let segments: Vec<&str> = path.split("::").filter(|s| !s.is_empty()).collect();
    let (mut base, mut rest): (Module, &[&str]) = match *segments.first()? {
        "crate" => (Vec::new(), &segments[1..]),
        "self" => (from.clone(), &segments[1..]),
        "super" => (from.clone(), &segments[..]),
        // A child module's name, as a `use` of `mod.rs` or `lib.rs` names it.
        _ => (from.clone(), &segments[..]),
    };
    while rest.first() == Some(&"super") {
        base.pop();
        rest = &rest[1..];
    }
    let mut found = None;
    for segment in rest {
        base.push(segment.to_string());
        if modules.contains(&base) {
            found = Some(base.clone());
        } else {
            break;
        }
    }
    found
}

/// The modules that the code of `from` imports, its ancestors left out.
fn imports(from: &Module, code: &str, modules: &BTreeSet<Module>) -> BTreeSet<Module> {
    paths_in(&code_of(code))
        .iter()
        .filter_map(|p| resolve(from, p, modules))
        .filter(|m| !from.starts_with(m))
        .collect()
}

/// The strongly connected components of more than one module (Tarjan).
fn cycles(edges: &BTreeMap<Module, BTreeSet<Module>>) -> Vec<BTreeSet<String>> {
    struct State<'a> {
        edges: &'a BTreeMap<Module, BTreeSet<Module>>,
        index: BTreeMap<&'a Module, usize>,
        low: BTreeMap<&'a Module, usize>,
        stack: Vec<&'a Module>,
        found: Vec<BTreeSet<String>>,
    }
    fn visit<'a>(v: &'a Module, s: &mut State<'a>) {
        let n = s.index.len();
        s.index.insert(v, n);
        s.low.insert(v, n);
        s.stack.push(v);
        for w in &s.edges[v] {
            if !s.index.contains_key(w) {
                visit(w, s);
                let low = s.low[v].min(s.low[w]);
                s.low.insert(v, low);
            } else if s.stack.contains(&w) {
                let low = s.low[v].min(s.index[w]);
                s.low.insert(v, low);
            }
        }
        if s.low[v] == s.index[v] {
            let mut component = BTreeSet::new();
            while let Some(w) = s.stack.pop() {
                component.insert(w.join("::"));
                if w == v {
                    break;
                }
            }
            if component.len() > 1 {
                s.found.push(component);
            }
        }
    }
    let mut state = State {
        edges,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        found: Vec::new(),
    };
    for v in edges.keys() {
        if !state.index.contains_key(v) {
            visit(v, &mut state);
        }
    }
    state.found
}

/// The import graph of the files under `src`.
fn import_graph(src: &Path) -> BTreeMap<Module, BTreeSet<Module>> {
    let mut files = Vec::new();
    rust_files(src, &mut files);
    let modules: BTreeSet<Module> = files.iter().map(|f| module_of(src, f)).collect();
    let mut edges = BTreeMap::new();
    for file in &files {
        let from = module_of(src, file);
        let code = std::fs::read_to_string(file).expect("a source file");
        let to = imports(&from, &code, &modules);
        edges.insert(from, to);
    }
    edges
}

#[test]
fn no_two_modules_of_the_library_import_each_other() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let graph = import_graph(&src);
    // The graph is read at all: the engine's driver imports the edge lists and the front.
    let propagate = graph
        .get(&vec!["mmp".to_string(), "propagate".to_string()])
        .expect("mmp/propagate.rs");
    for m in ["wedge_lists", "front"] {
        let m = vec!["mmp".to_string(), m.to_string()];
        assert!(propagate.contains(&m), "propagate.rs imports {m:?}");
    }
    let found = cycles(&graph);
    assert!(found.is_empty(), "import cycles: {found:?}");
}

#[test]
fn a_cycle_through_a_use_tree_is_found() {
    let modules: BTreeSet<Module> = [vec!["a".to_string()], vec!["b".to_string()]].into();
    let mut graph = BTreeMap::new();
    for (from, code) in [
        ("a", "use crate::{b::X, c};"),
        ("b", "fn f() { super::a::g() }"),
    ] {
        let from = vec![from.to_string()];
        let to = imports(&from, code, &modules);
        graph.insert(from, to);
    }
    let found = cycles(&graph);
    assert_eq!(found.len(), 1, "{graph:?}");
    assert_eq!(found[0], ["a".to_string(), "b".to_string()].into());
}
