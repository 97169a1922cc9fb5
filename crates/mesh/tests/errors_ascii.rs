//! Malformed ASCII MSH files: each case edits one line of a small valid file and asserts the
//! error variant and the 1-based line it reports.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d_mesh::{Location, MeshError, MshFormat, NodeId, parse_msh, parse_msh_with_report};

/// A unit square split into two triangles, one named edge; node tags 10, 20, 30, 40.
///
/// ```text
///   40 ---- 30
///   |  3  / |
///   |   /   |      element 1: line 10-20 ("edge"), elements 2, 3: triangles ("body")
///   | /  2  |
///   10 ---- 20
/// ```
const V41: &str = "$MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
2
1 10 \"edge\"
2 20 \"body\"
$EndPhysicalNames
$Entities
0 1 1 0
1 0 0 0 1 0 0 1 10 0
1 0 0 0 1 1 0 1 20 0
$EndEntities
$Nodes
1 4 10 40
2 1 0 4
10
20
30
40
0 0 0
1 0 0
1 1 0
0 1 0
$EndNodes
$Elements
2 3 1 3
1 1 1 1
1 10 20
2 1 2 2
2 10 20 30
3 10 30 40
$EndElements
";

/// The same mesh in MSH 2.2.
const V22: &str = "$MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
2
1 10 \"edge\"
2 20 \"body\"
$EndPhysicalNames
$Nodes
4
10 0 0 0
20 1 0 0
30 1 1 0
40 0 1 0
$EndNodes
$Elements
3
1 1 2 10 1 10 20
2 2 2 20 1 10 20 30
3 2 2 20 1 10 30 40
$EndElements
";

/// `base` with line `n` (1-based) replaced by `new` (several lines allowed, or none).
fn edit(base: &str, n: usize, new: Option<&str>) -> String {
    let mut lines: Vec<&str> = base.lines().collect();
    match new {
        Some(text) => lines[n - 1] = text,
        None => {
            lines.remove(n - 1);
        }
    }
    lines.join("\n") + "\n"
}

/// Asserts a `Msh` error at line `line`, whose reason mentions `needle`.
fn assert_msh(text: &str, line: usize, needle: &str) {
    match parse_msh(text.as_bytes()) {
        Err(MeshError::Msh { at, reason }) => {
            assert_eq!(at, Location::Line(line), "{reason}\n{text}");
            assert!(reason.contains(needle), "'{reason}' lacks '{needle}'");
        }
        other => panic!("expected an Msh error at line {line}, got {other:?}\n{text}"),
    }
}

fn assert_unsupported(text: &str, line: usize, needle: &str) {
    match parse_msh(text.as_bytes()) {
        Err(MeshError::Unsupported { at, what }) => {
            assert_eq!(at, Location::Line(line), "{what}");
            assert!(what.contains(needle), "'{what}' lacks '{needle}'");
        }
        other => panic!("expected Unsupported at line {line}, got {other:?}"),
    }
}

#[test]
fn the_base_files_load_to_the_same_mesh() {
    let a = parse_msh(V41.as_bytes()).unwrap();
    let b = parse_msh(V22.as_bytes()).unwrap();
    assert_eq!(a, b);
    assert_eq!(a.node_tags, vec![10, 20, 30, 40]);
    assert_eq!(a.blocks[1].nodes, [0, 1, 2, 0, 2, 3].map(NodeId).to_vec());
    assert_eq!(a.group_cell_count("body").unwrap(), 2);
    assert_eq!(a.group_nodes("edge").unwrap(), vec![NodeId(0), NodeId(1)]);
}

#[test]
fn bad_numbers() {
    assert_msh(&edit(V41, 22, Some("1 x 0")), 22, "expected y");
    assert_msh(&edit(V41, 16, Some("2 1 0 four")), 16, "found 'four'");
    assert_msh(&edit(V41, 29, Some("1 10 -20")), 29, "'-20'");
    assert_msh(&edit(V22, 12, Some("20 1 0.0.0 0")), 12, "expected y");
    assert_msh(&edit(V22, 18, Some("1 1 2 10 1 10 2e1")), 18, "'2e1'");
}

#[test]
fn non_finite_coordinates() {
    assert_msh(&edit(V41, 22, Some("nan 0 0")), 22, "not finite");
    assert_msh(&edit(V41, 23, Some("1 inf 0")), 23, "not finite");
    assert_msh(&edit(V22, 13, Some("30 1 1 -inf")), 13, "not finite");
}

#[test]
fn non_zero_z() {
    assert_msh(&edit(V41, 23, Some("1 1 1e-3")), 23, "z = 1e-3");
    assert_msh(&edit(V22, 14, Some("40 0 1 -2e-6")), 14, "z = 2e-6");
    // Rounding noise passes.
    parse_msh(edit(V41, 23, Some("1 1 1e-13")).as_bytes()).unwrap();
}

#[test]
fn duplicate_tags() {
    assert_msh(&edit(V41, 18, Some("10")), 18, "node tag 10 appears twice");
    assert_msh(&edit(V22, 12, Some("10 1 0 0")), 12, "node tag 10 appears twice");
    assert_msh(&edit(V41, 32, Some("2 10 30 40")), 32, "element tag 2 appears twice");
    assert_msh(&edit(V22, 20, Some("1 2 2 20 1 10 30 40")), 20, "element tag 1");
}

#[test]
fn missing_nodes() {
    assert_msh(&edit(V41, 31, Some("2 10 20 99")), 31, "refers to node 99");
    assert_msh(&edit(V22, 19, Some("2 2 2 20 1 10 20 31")), 19, "refers to node 31");
}

#[test]
fn wrong_counts() {
    // Header total larger than the blocks.
    assert_msh(&edit(V41, 15, Some("1 5 10 40")), 15, "declares 5 nodes");
    assert_msh(&edit(V41, 27, Some("2 4 1 3")), 27, "declares 4 elements");
    // A block declares more nodes than its lines: the first coordinate line is read as a tag.
    assert_msh(&edit(V41, 16, Some("2 1 0 5")), 21, "where the line should end");
    // A block declares fewer elements than follow.
    let fewer = edit(&edit(V41, 27, Some("2 2 1 2")), 30, Some("2 1 2 1"));
    assert_msh(&fewer, 32, "expected $EndElements");
    // MSH 2.2 counts.
    assert_msh(&edit(V22, 17, Some("4")), 21, "section ends before");
    assert_msh(&edit(V22, 10, Some("3")), 14, "expected $EndNodes");
    // A count that cannot fit in the file.
    assert_msh(&edit(V41, 15, Some("1 400 10 40")), 15, "bytes remain");
    assert_msh(&edit(V22, 17, Some("18446744073709551615")), 17, "bytes remain");
    assert_msh(&edit(V41, 5, Some("1000000")), 5, "cannot fit");
    assert_msh(&edit(V41, 5, Some("3")), 8, "section ends before");
}

#[test]
fn truncated_files() {
    let cut = |n: usize| V41.lines().take(n).collect::<Vec<_>>().join("\n");
    assert_msh(&cut(24), 24, "ends before $EndNodes");
    // Counts that the rest of the file cannot hold are caught where they are.
    assert_msh(&(cut(30) + "\n2 10"), 30, "bytes remain");
    assert_msh(&cut(20), 15, "bytes remain");
    // Truncated inside the last record.
    assert_msh(&(cut(31) + "\n3 10 30"), 32, "expected a node tag, found end of file");
    let cut22 = |n: usize| V22.lines().take(n).collect::<Vec<_>>().join("\n") + "\n";
    assert_msh(&cut22(19), 20, "expected an element tag, found end of file");
}

#[test]
fn missing_end_markers() {
    assert_msh(&edit(V41, 25, None), 25, "expected $EndNodes, found '$Elements'");
    assert_msh(&edit(V41, 33, None), 33, "ends before $EndElements");
    assert_msh(&edit(V41, 3, None), 3, "expected $EndMeshFormat");
    assert_msh(&edit(V22, 8, None), 8, "expected $EndPhysicalNames");
    assert_msh(&edit(V22, 15, Some("$EndNode")), 15, "expected $EndNodes");
}

#[test]
fn unnamed_physical_groups() {
    // Entity curve 1 uses physical tag 10, now unnamed.
    assert_msh(&edit(V41, 6, Some("1 11 \"edge\"")), 11, "physical tag 10");
    // Element 2 is the first to use physical tag 20.
    assert_msh(&edit(V22, 7, Some("2 21 \"body\"")), 19, "Physical Surface(\"name\", 20)");
    // A file without $PhysicalNames whose elements carry no physical tag is fine.
    let text = V22
        .replace("1 1 2 10 1 10 20", "1 1 2 0 1 10 20")
        .replace("2 2 2 20 1 10 20 30\n3 2 2 20 1 10 30 40", "2 2 2 0 1 10 20 30\n3 2 2 0 1 10 30 40");
    let text = edit(&edit(&edit(&edit(&edit(&text, 4, None), 4, None), 4, None), 4, None), 4, None);
    let mesh = parse_msh(text.as_bytes()).unwrap();
    assert!(mesh.groups.is_empty());
    assert!(mesh.blocks.iter().all(|b| b.physical_tags.is_empty()));
}

#[test]
fn unsupported_content() {
    assert_unsupported(&edit(V41, 30, Some("2 1 4 2")), 30, "element type 4");
    assert_unsupported(&edit(V22, 19, Some("2 21 2 20 1 10 20 30")), 19, "element type 21");
    assert_unsupported(&edit(V41, 2, Some("4 0 8")), 2, "MSH version 4");
    assert_unsupported(&edit(V41, 2, Some("3.0 0 8")), 2, "MSH version 3.0");
    let partitioned = edit(V41, 13, Some("$EndEntities\n$PartitionedEntities\n1\n0\n$EndPartitionedEntities"));
    assert_unsupported(&partitioned, 14, "$PartitionedEntities");
}

#[test]
fn harmless_sections_are_skipped_and_reported() {
    let text = V41.to_string()
        + "$NodeData\n1\n\"u\"\n1\n0.0\n3\n0\n1\n4\n10 1\n20 2\n30 3\n40 4\n$EndNodeData\n\
           $Periodic\n0\n$EndPeriodic\n$Comments\nanything $EndComments\n$EndComments\n";
    let (mesh, report) = parse_msh_with_report(text.as_bytes()).unwrap();
    assert_eq!(mesh, parse_msh(V41.as_bytes()).unwrap());
    assert_eq!(report.format, MshFormat::V41Ascii);
    assert_eq!(report.skipped_sections, ["NodeData", "Periodic", "Comments"]);
    assert_msh(&(V41.to_string() + "$Periodic\n0\n"), 34, "has no $EndPeriodic");
}

#[test]
fn section_order_and_repetition() {
    let nodes: String = V41.lines().skip(13).take(12).collect::<Vec<_>>().join("\n");
    assert_msh(&(V41.to_string() + &nodes + "\n"), 34, "a second $Nodes");
    let without_nodes = V41.replace(&nodes, "");
    assert_msh(&without_nodes, 15, "$Elements must come after $Nodes");
    let elements_only: String = V41.lines().take(25).collect::<Vec<_>>().join("\n") + "\n";
    assert_msh(&elements_only, 26, "no $Elements section");
    assert_msh(&V22.replace("$Nodes", "$Entities\n$EndEntities\n$Nodes"), 9, "not part of MSH 2.2");
    assert_msh("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n42\n", 4, "expected a section");
    assert_msh("hello", 1, "not an MSH file");
    assert_msh("", 1, "empty file");
}

#[test]
fn entity_errors() {
    assert_msh(&edit(V41, 28, Some("1 5 1 1")), 28, "curve 5, which $Entities does not list");
    assert_msh(&edit(V41, 12, Some("1 0 0 0 1 1 0 1 20")), 12, "bounding entities");
    assert_msh(&edit(V41, 16, Some("7 1 0 4")), 16, "entity dimension 7");
}

#[test]
fn windows_line_endings_and_blank_lines_are_accepted() {
    let crlf = V41.replace('\n', "\r\n");
    assert_eq!(parse_msh(crlf.as_bytes()).unwrap(), parse_msh(V41.as_bytes()).unwrap());
    let blank = V22.replace("$EndNodes\n", "$EndNodes\n\n\n").replace("\n10 0 0 0", "\n\n10 0 0 0");
    assert_eq!(parse_msh(blank.as_bytes()).unwrap(), parse_msh(V22.as_bytes()).unwrap());
    // Line numbers count the blank lines.
    assert_msh(&blank.replace("20 1 0 0", "20 1 0 x"), 13, "'x'");
}
