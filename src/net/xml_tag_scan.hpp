// A scan of an XML text's start tags without building a document: how the on-demand net index
// (NetSource::scan) finds where a net's elements are in a 100 MB file at a fraction of a parse's
// cost and memory (a pugixml document is about twice the size of its text).
//
// It reports the start tags of the root element (depth 0), of its children (1) and of theirs (2),
// with their offsets and raw attribute text, and checks the structure as it goes: names, attribute
// syntax, matching end tags, terminated comments, CDATA sections and processing instructions. It
// declines (returns false) a text it cannot read exactly as pugixml does, which is then parsed
// whole: a byte order mark, an encoding other than UTF-8, a DOCTYPE, a NUL byte, or any structural
// error (the parse then gives the error's description). A text it accepts has the elements pugixml
// would give (entities and whitespace in the values it returns are decoded as pugixml decodes
// them); errors it does not look for (an unknown entity, a bad character) are SUMO's to report.
// Private to src/net.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace signalsim::sumo {

/// One start tag as it is in the text.
struct StartTag {
  std::string_view name;
  std::string_view attributes;  ///< the raw text between the name and its '>' or '/>'
  std::size_t begin = 0;        ///< the offset of its '<'
  int depth = 0;                ///< 0 for the root, 1 for a child of the root, 2 below that
};

class StartTagVisitor {
 public:
  virtual ~StartTagVisitor() = default;
  virtual void start(const StartTag& tag) = 0;
};

/// Calls `visitor.start` for the start tags of depth 0 to 2 of the first root element, in text order.
/// False when the text is declined (see the file comment); the visitor may have been called.
bool scan_start_tags(std::string_view text, StartTagVisitor& visitor);

/// The raw value of attribute `name` of `tag` (between its quotes), or nullopt when it has none.
std::optional<std::string_view> raw_attribute(const StartTag& tag, std::string_view name);

/// The value of attribute `name` as pugixml gives it (entities decoded; tabs and line ends made
/// spaces), "" when the tag has none: a view of the text when the raw value needs no decoding, else
/// of `scratch`, which holds the decoded value.
std::string_view attribute_value(const StartTag& tag, std::string_view name, std::string& scratch);

}  // namespace signalsim::sumo
