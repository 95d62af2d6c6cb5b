// JSON Schemas of input files, generated from their key tables (scenario/key_table.hpp) and the
// parameter schema: what `signalsim schema scenario|sweep` prints, for editors (yaml-language-server
// reads `# yaml-language-server: $schema=<file>` at the top of a YAML file; docs/schema.md).
//
// Draft-07: yaml-language-server validates and completes with draft-07 (newer drafts are not fully
// supported there). Output is deterministic: objects keep the tables' order; parameters and `--set`
// keys are sorted by name.
//
// The schema checks keys, shapes, ranges and choices; rules across keys stay the loader's (to_s
// >= from_s, base_link_to_front <= length, at most one pull_out, a parameter given twice, ...).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "scenario/key_table.hpp"

namespace signalsim {

using SchemaJson = nlohmann::ordered_json;

/// The schema of one key's value.
SchemaJson key_schema(const KeySpec& key);

/// The schema of a mapping with `table`'s keys: each key's schema, the required ones, at least one
/// of each `one_of_required` group, `needs` as draft-07 dependencies, no other key.
SchemaJson mapping_schema(const KeyTable& table);

/// A whole schema document for files whose top-level mapping is `top`: $schema, title, the mapping,
/// and the definitions its keys refer to (parameters; `--set` keys for sweep files).
SchemaJson schema_document(const KeyTable& top, const std::string& title);

/// `document` as text: two-space indents, a final line break.
std::string schema_text(const SchemaJson& document);

}  // namespace signalsim
