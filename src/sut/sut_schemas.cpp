// The protocol's JSON Schemas; see sut_schemas.hpp. Written out here, field by field as
// sut_messages.cpp writes them; tests validate real messages of a run against them.
#include "sut/sut_schemas.hpp"

#include <nlohmann/json.hpp>

namespace signalsim {
namespace {

using Json = nlohmann::ordered_json;

const char* const kDefinitions = R"({
  "lanelet": {
    "type": "object", "additionalProperties": false,
    "required": ["id", "edge", "junction", "s_start", "s_end", "length", "speed_limit", "turn_direction",
                 "successor_turns", "roundabout_role", "roundabout_id", "leaves_ring_at_end", "turn_signal_distance", "tags", "centerline"],
    "properties": {
      "id": {"type": "string", "description": "SUMO lane id"},
      "edge": {"type": "string"},
      "junction": {"type": "string", "description": "the junction of an internal lane, else empty"},
      "s_start": {"type": "number", "description": "[m] route s of the lane's start"},
      "s_end": {"type": "number", "description": "[m] route s of the lane's end"},
      "length": {"type": "number", "minimum": 0, "description": "[m]"},
      "speed_limit": {"type": "number", "description": "[m/s]"},
      "turn_direction": {"enum": ["none", "straight", "left", "right"]},
      "successor_turns": {"type": "array", "items": {"enum": ["none", "straight", "left", "right"]}},
      "roundabout_role": {"enum": ["none", "entry", "internal", "exit"]},
      "roundabout_id": {"type": "string"},
      "leaves_ring_at_end": {"type": "boolean"},
      "turn_signal_distance": {"type": ["number", "null"], "description": "[m] null: none"},
      "tags": {"type": "object", "additionalProperties": {"type": "string"}},
      "centerline": {"type": "array", "items": {"type": "array", "items": {"type": "number"}, "minItems": 2, "maxItems": 2}}
    }
  },
  "shift_line": {
    "type": "object", "additionalProperties": false, "required": ["module", "edge", "s_start", "s_end", "shift"],
    "properties": {
      "module": {"enum": ["lane_change", "avoidance", "pull_out", "pull_over", "none"]},
      "edge": {"type": "string"}, "s_start": {"type": "number"}, "s_end": {"type": "number"},
      "shift": {"type": "number", "description": "[m] lateral, left positive"}
    }
  },
  "hello": {
    "type": "object", "additionalProperties": false,
    "required": ["type", "protocol", "role", "scenario", "step_length", "vehicle_length", "base_link_to_front",
                 "parameters", "lanelets", "shift_lines"],
    "properties": {
      "type": {"const": "hello"}, "protocol": {"const": 1}, "role": {"const": "ROLE"},
      "scenario": {"type": "string"},
      "step_length": {"type": "number", "exclusiveMinimum": 0, "description": "[s]"},
      "vehicle_length": {"type": "number", "description": "[m]"},
      "base_link_to_front": {"type": "number", "description": "[m]"},
      "parameters": {"type": "object", "additionalProperties": {"type": "string"}},
      "lanelets": {"type": "array", "items": {"$ref": "#/definitions/lanelet"}},
      "shift_lines": {"type": "array", "items": {"$ref": "#/definitions/shift_line"}}
    }
  },
  "element": {
    "type": "object", "additionalProperties": false, "required": ["color", "shape", "status", "confidence"],
    "properties": {
      "color": {"enum": ["unknown", "red", "amber", "green", "white"]},
      "shape": {"enum": ["unknown", "circle", "left_arrow", "right_arrow", "up_arrow", "up_left_arrow", "up_right_arrow",
                         "down_arrow", "down_left_arrow", "down_right_arrow", "cross"]},
      "status": {"enum": ["unknown", "solid_off", "solid_on", "flashing"]},
      "confidence": {"type": ["number", "null"]}
    }
  },
  "light": {
    "type": "object", "additionalProperties": false,
    "required": ["tls_id", "link_index", "lanelet_index", "stop_line_s", "distance", "delivered", "elements", "time_to_red"],
    "properties": {
      "tls_id": {"type": "string"}, "link_index": {"type": "integer"},
      "lanelet_index": {"type": "integer", "minimum": 0},
      "stop_line_s": {"type": "number", "description": "[m]"}, "distance": {"type": "number", "description": "[m]"},
      "delivered": {"type": "boolean"},
      "elements": {"type": "array", "items": {"$ref": "#/definitions/element"}},
      "time_to_red": {"type": ["number", "null"], "description": "[s] null without V2I"}
    }
  },
  "step": {
    "type": "object", "additionalProperties": false, "required": ["type", "time", "ego", "window", "request", "lights"],
    "properties": {
      "type": {"const": "step"}, "time": {"type": "number", "description": "[s]"},
      "ego": {
        "type": "object", "additionalProperties": false,
        "required": ["x", "y", "yaw", "speed", "accel", "s_front", "s_base"],
        "properties": {"x": {"type": "number"}, "y": {"type": "number"}, "yaw": {"type": "number"},
                       "speed": {"type": "number"}, "accel": {"type": "number"},
                       "s_front": {"type": "number"}, "s_base": {"type": "number"}}
      },
      "window": {
        "type": "object", "additionalProperties": false, "required": ["first", "last", "lanelets"],
        "properties": {"first": {"type": "integer", "minimum": 0}, "last": {"type": "integer", "minimum": 0},
                       "lanelets": {"type": "array", "items": {"type": "string"}}}
      },
      "request": {
        "type": "object", "additionalProperties": false,
        "required": ["module", "turn", "hazard", "desired_start", "desired_end", "required_start", "required_end"],
        "properties": {
          "module": {"enum": ["none", "intersection", "roundabout_entry", "roundabout_exit", "lane_change", "avoidance",
                              "pull_out", "pull_over", "sumo", "sut"]},
          "turn": {"enum": ["no_command", "disable", "left", "right"]},
          "hazard": {"enum": ["no_command", "disable", "enable"]},
          "desired_start": {"type": "number"}, "desired_end": {"type": "number"},
          "required_start": {"type": "number"}, "required_end": {"type": "number"}
        }
      },
      "lights": {"type": "array", "items": {"$ref": "#/definitions/light"}}
    }
  },
  "bye": {"type": "object", "additionalProperties": false, "required": ["type"], "properties": {"type": {"const": "bye"}}}
})";

const char* const kDeciderReply = R"({
  "type": "object", "required": ["blinker"],
  "properties": {"blinker": {"enum": ["none", "left", "right", "hazard"]}}
})";

const char* const kLightJudgeReply = R"({
  "type": "object", "required": ["lights"],
  "properties": {
    "lights": {
      "type": "array", "description": "one answer per light of the step, in its order",
      "items": {
        "type": "object", "required": ["tls_id", "decision"],
        "properties": {"tls_id": {"type": "string"}, "decision": {"enum": ["stop", "go"]},
                       "reason": {"type": "string"}}
      }
    }
  }
})";

std::string text_of(const Json& schema) { return schema.dump(2) + "\n"; }

}  // namespace

std::string sut_request_schema(const std::string& role) {
  Json definitions = Json::parse(kDefinitions);
  definitions["hello"]["properties"]["role"]["const"] = role;
  if (role == "decider") definitions["step"]["properties"]["lights"]["maxItems"] = 0;
  Json schema{{"$schema", "http://json-schema.org/draft-07/schema#"},
              {"title", "signalsim JSON-lines message to a " + role + " (hello, step or bye)"},
              {"oneOf", Json::array({{{"$ref", "#/definitions/hello"}}, {{"$ref", "#/definitions/step"}},
                                     {{"$ref", "#/definitions/bye"}}})},
              {"definitions", std::move(definitions)}};
  return text_of(schema);
}

std::string sut_reply_schema(const std::string& role) {
  Json schema{{"$schema", "http://json-schema.org/draft-07/schema#"},
              {"title", "signalsim JSON-lines reply of a " + role + " to one step"}};
  const Json reply = Json::parse(role == "decider" ? kDeciderReply : kLightJudgeReply);
  for (const auto& [key, value] : reply.items()) schema[key] = value;
  return text_of(schema);
}

}  // namespace signalsim
