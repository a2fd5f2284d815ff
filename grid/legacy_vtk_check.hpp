#pragma once
#include <string>

namespace cellproj {

// Checks what VTK's legacy reader follows without bounds, before it runs: the version line (a
// garbled one makes it read a format-5 file as the older layout) and, before format 5, the CELLS
// block, where each cell is a count and that many ids, `size` numbers in all; a count that runs
// past the block corrupts the reader's heap. Throws InputError naming the file and the cell.
void check_legacy_cells(const std::string& path);

// Walks an unstructured or structured grid's dataset blocks (POINTS, CELLS, CELL_TYPES; DIMENSIONS)
// and then its POINT_DATA and CELL_DATA arrays as VTK's legacy reader does, and checks each FIELD
// block: that reader uses what its field reader returns at the dataset level without a check, so a
// block it cannot read (no array count, a garbled array header, an unknown type, values missing)
// crashes it, and it reads arrays of a negative count anywhere. Throws InputError naming the file,
// the block and the array.
// Polyhedra (type 42) are refused from CELL_TYPES, naming the first: cellproj does not render them,
// and VTK decomposes their face streams unchecked (a garbled one crashed it).
// check_legacy_cells calls it; `binary` and `major` are the header's.
void check_legacy_fields(const std::string& path, bool binary, int major);

// Whether the file's DATASET line names `type` ("structured_grid"), matched as VTK's readers match
// it: by prefix, in any case.
bool legacy_dataset_is(const std::string& path, const std::string& type);

// For both checks: whether `word` is `keyword` in any case (VTK reads keywords so), and the bytes
// of one binary OFFSETS or CONNECTIVITY value of `type` (0: not an id type VTK writes).
bool is_legacy_keyword(std::string word, const std::string& keyword);
int legacy_id_bytes(const std::string& type);

}  // namespace cellproj
