// fconv --info: what is known about a file, as JSON.

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/file_io.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/table/table_io.hpp"
#include "formats/volume/volume_io.hpp"
#include "mesh_input.hpp"

namespace fest::fconv_tool {

using namespace fest::formats;

namespace {

// What is known about the input before its content is parsed.
nlohmann::json file_facts(const Input& in) {
  return {{"file", in.name},
          {"kind", kind_name(kind_of(in.format))},
          {"format", format_name(in.format)},
          {"gzip", in.was_gzip},
          {"bytes", in.bytes.size()}};
}

nlohmann::json describe(const Input& in) {
  nlohmann::json facts = file_facts(in);
  nlohmann::json content;
  switch (kind_of(in.format)) {
    case Kind::mesh: content = describe_mesh(read_whole_mesh(in)); break;
    case Kind::image: content = describe_image(parse(in, read_image)); break;
    case Kind::volume: content = describe_volume(parse(in, read_volume)); break;
    case Kind::dataset: content = describe_dataset(parse(in, read_dataset)); break;
    case Kind::table: content = describe_table(parse(in, read_table)); break;
    case Kind::json: {
      nlohmann::json doc = parse(in, read_json_document);
      content = {{"type", doc.type_name()}, {"size", doc.size()}};
      break;
    }
  }
  facts.update(content);
  return facts;
}

}  // namespace

int info_command(const InfoOptions& o) {
  const Input in = load_input(o.input);
  write_output(o.output, describe(in).dump(2) + "\n");
  return 0;
}

}  // namespace fest::fconv_tool
