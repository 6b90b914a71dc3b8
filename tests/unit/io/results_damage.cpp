#include "results_damage.hpp"

#include <hdf5.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "styk/io/results_file.hpp"
#include "styk/io/results_seal.hpp"

namespace styk::damage {
namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::runtime_error("damage helper: " + what);
}

std::fstream open_in_place(const std::string& file) {
  std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
  require(bool(f), "cannot open " + file);
  return f;
}

bool starts_with_seal(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::string head(18, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  return bool(in) && head == "styk-results-seal ";
}

// Runs `damage` on `file`, sealing it again afterwards when asked and it was sealed.
template <class Damage>
void beneath_seal(const std::string& file, Seal seal, Damage damage) {
  const bool was_sealed = seal == Seal::Reseal && starts_with_seal(file);
  damage();
  if (!was_sealed) return;
  try {
    io::seal_results_file(file);
  } catch (const std::runtime_error&) {
    // The damage moved or destroyed HDF5's superblock: there is nothing left to seal.
  }
}

}  // namespace

StoredBytes first_chunk(const std::string& file, const std::string& dataset) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  require(f >= 0, "cannot open " + file);
  const hid_t d = H5Dopen2(f, dataset.c_str(), H5P_DEFAULT);
  require(d >= 0, "no dataset " + dataset);
  const hid_t space = H5Dget_space(d);
  hsize_t offset[2] = {0, 0};
  unsigned mask = 0;
  haddr_t address = 0;
  hsize_t size = 0;
  const herr_t status = H5Dget_chunk_info(d, space, 0, offset, &mask, &address, &size);
  // HDF5's addresses count from its superblock, which a sealed file's user block precedes.
  const hid_t creation = H5Fget_create_plist(f);
  hsize_t user_block = 0;
  const herr_t block_status = H5Pget_userblock(creation, &user_block);
  H5Pclose(creation);
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
  require(status >= 0 && size > 0, dataset + " has no stored chunk");
  require(block_status >= 0, "cannot read the user block size of " + file);
  return {address + user_block, size};
}

void copy_file(const std::string& from, const std::string& to) {
  std::filesystem::copy_file(from, to, std::filesystem::copy_options::overwrite_existing);
}

std::uint64_t file_size(const std::string& file) { return std::filesystem::file_size(file); }

void flip_byte(const std::string& file, std::uint64_t offset, Seal seal) {
  beneath_seal(file, seal, [&] {
    std::fstream f = open_in_place(file);
    f.seekg(static_cast<std::streamoff>(offset));
    char byte = 0;
    f.get(byte);
    f.seekp(static_cast<std::streamoff>(offset));
    f.put(static_cast<char>(~byte));
    require(bool(f), "cannot flip a byte of " + file);
  });
}

void truncate_file(const std::string& file, std::uint64_t size, Seal seal) {
  beneath_seal(file, seal, [&] { std::filesystem::resize_file(file, size); });
}

void zero_bytes(const std::string& file, std::uint64_t offset, std::uint64_t size, Seal seal) {
  beneath_seal(file, seal, [&] {
    std::fstream f = open_in_place(file);
    f.seekp(static_cast<std::streamoff>(offset));
    const std::vector<char> zeros(size, 0);
    f.write(zeros.data(), static_cast<std::streamsize>(size));
    require(bool(f), "cannot zero bytes of " + file);
  });
}

void reseal(const std::string& file) { io::seal_results_file(file); }

void set_value(const std::string& file, const std::string& dataset, std::uint64_t row,
               std::uint64_t column, double value, Seal seal) {
  beneath_seal(file, seal, [&] {
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    require(f >= 0, "cannot open " + file);
    const hid_t d = H5Dopen2(f, dataset.c_str(), H5P_DEFAULT);
    require(d >= 0, "no dataset " + dataset);
    const hid_t space = H5Dget_space(d);
    const int rank = H5Sget_simple_extent_ndims(space);
    const hsize_t start[2] = {row, column};
    const hsize_t one[2] = {1, 1};
    H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, one, nullptr);
    const hid_t memory = H5Screate_simple(1, one, nullptr);
    const herr_t status = H5Dwrite(d, H5T_NATIVE_DOUBLE, memory, space, H5P_DEFAULT, &value);
    H5Sclose(memory);
    H5Sclose(space);
    H5Dclose(d);
    H5Fclose(f);
    require(status >= 0 && rank >= 1, "cannot write into " + dataset);
  });
}

std::string write_cube_results(const std::string& path) {
  Model model;
  const Vec3 corners[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                           {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int i = 0; i < 8; ++i) model.add_node(i + 1, corners[i], {});
  model.add_element(1, "C3D8", {0, 1, 2, 3, 4, 5, 6, 7}, {});
  model.nsets["TOP"] = NodeSet{"TOP", {4, 5, 6, 7}, {}};
  model.elsets["EALL"] = ElementSet{"EALL", {0}, {}};
  Results results;
  for (int step = 1; step <= 2; ++step) {
    IncrementResult inc;
    inc.step = step;
    inc.increment = 1;
    inc.step_time = 1.0;
    inc.total_time = step;
    for (const Vec3& x : model.coords) {
      inc.U.push_back({1e-3 * step * x[0], -2e-4 * x[1], 5e-4 * step * x[2]});
      inc.RF.push_back({0.0, 0.0, x[2] == 0.0 ? -25.0 * step : 0.0});
      inc.S_nodal_I.push_back({100.0 * step, 0, 0, 0, 0, x[2]});
      inc.S_nodal_II.push_back({100.0 * step, 0, 0, 0, 0, 0});
    }
    inc.ip_offset = {0, 8};
    for (int p = 0; p < 8; ++p) {
      inc.S.push_back({100.0 * step, 1.0 * p, 0, 0, 0, 0});
      inc.E.push_back({5e-4 * step, 0, 0, 0, 0, 1e-5 * p});
      inc.S_element_nodes.push_back({100.0 * step, 0, 0, 0, 0, 0});
    }
    inc.S_centroid = {{100.0 * step, 0, 0, 0, 0, 0}};
    for (int n = 4; n < 8; ++n) {
      ContactNodeResult c;
      c.node = n;
      c.status = ContactStatus::Stick;
      c.area = 0.25;
      c.pressure = 10.0 * step;
      c.normal = {0, 0, 1};
      c.t1 = {1, 0, 0};
      c.t2 = {0, 1, 0};
      c.force = {0, 0, -2.5 * step};
      inc.contact.push_back(c);
    }
    inc.contact_pairs.push_back({{0, 0, -10.0 * step}, {0, 0, 0}});
    results.increments.push_back(inc);
  }
  write_results_file(path, model, results);
  return path;
}

}  // namespace styk::damage
