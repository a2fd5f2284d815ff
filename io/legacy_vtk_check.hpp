#pragma once
#include <cstdint>
#include <istream>
#include <string>

#include "base/error.hpp"

namespace cellproj {

// Checks what VTK's legacy reader follows without bounds, before it runs: the version line (a
// garbled one makes it read a format-5 file as the older layout) and, before format 5, the CELLS
// block, where each cell is a count and that many ids, `size` numbers in all; a count that runs
// past the block corrupts the reader's heap (the walk below checks it, finding the block as VTK
// does: keywords by prefix in any case, after any whitespace). Throws InputError naming the file
// and the cell.
void check_legacy_cells(const std::string& path);

// Walks an unstructured or structured grid's dataset blocks (POINTS, CELLS and their counts or
// format 5's arrays, CELL_TYPES; DIMENSIONS) and then its POINT_DATA and CELL_DATA arrays as VTK's legacy reader does,
// and checks each FIELD block: that reader uses what its field reader returns at the dataset level without a check, so
// a block it cannot read (no array count, a garbled array header, an unknown type, values missing) crashes it, and it
// reads arrays of a negative count anywhere. Throws InputError naming the file, the block and the array. Polyhedra
// (type 42) are refused from CELL_TYPES, naming the first: cellproj does not render them, and VTK decomposes their face
// streams unchecked (a garbled one crashed it). check_legacy_cells calls it; `binary` and `major` are the header's.
void check_legacy_fields(const std::string& path, bool binary, int major);

// The encoding of the legacy file at `path` as VTK's reader finds it: the first word after the title
// line, past any blank lines, starting with "ascii" or "binary" in any case ("bINARY" is binary to
// VTK). A fuzzed file with a blank third line was BINARY to VTK, and the checks that read the third
// line took it for unknown and let VTK's reader crash on its CELLS.
enum class LegacyEncoding { ascii, binary, unknown };
LegacyEncoding legacy_file_encoding(const std::string& path);

// The offsets of n cells, at(0) .. at(n): cell c's point ids are connectivity entries at(c) up to
// at(c + 1), so the offsets start at 0 and climb, never past the `ids` connectivity entries. VTK's
// cell array takes them as they are (walking garbled ones crashed its reader). Throws InputError,
// without the file's name, naming the first cell that does not fit.
template <class At>
void check_offsets(At&& at, std::int64_t n, std::int64_t ids) {
  if (n > 0 && at(0) != 0) throw InputError("the cell offsets start at " + std::to_string(at(0)) + ", not 0");
  for (std::int64_t c = 0; c < n; ++c)
    if (at(c + 1) < at(c) || at(c + 1) > ids)
      throw InputError("cell " + std::to_string(c) + "'s point ids run from offset " + std::to_string(at(c)) + " to " +
                       std::to_string(at(c + 1)) + ", outside the " + std::to_string(ids) +
                       " connectivity ids or backwards");
}

// The dataset type a legacy file declares, lower case ("structured_grid", ...), read as VTK's readers
// read it: two lines (the version, the title), then words (the encoding, DATASET, the type; a
// vertical tab may join them on one line). Leaves `in` after the type; "" when there is no DATASET.
std::string read_legacy_dataset_type(std::istream& in);

// Whether the file's DATASET line names `type` ("structured_grid"), matched as VTK's readers match
// it: by prefix, in any case.
bool legacy_dataset_is(const std::string& path, const std::string& type);

// For both checks: whether `word` is `keyword` in any case (VTK reads keywords so), and the bytes
// of one binary OFFSETS or CONNECTIVITY value of `type` (0: not an id type VTK writes).
bool is_legacy_keyword(std::string word, const std::string& keyword);
int legacy_id_bytes(const std::string& type);

}  // namespace cellproj
