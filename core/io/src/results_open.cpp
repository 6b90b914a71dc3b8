#include "results_open.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace styk::io {

h5::Handle open_results_for_reading(const std::string& path, std::optional<ResultsSeal>* seal) {
  if (FILE* probe = std::fopen(path.c_str(), "rb"))
    std::fclose(probe);
  else
    throw std::runtime_error(std::string("cannot be opened: ") + std::strerror(errno));
  // Before HDF5 sees a byte: damaged metadata can make HDF5 over-read its buffers or allocate
  // gigabytes before it reports the file damaged (docs/fuzzing.md).
  const std::optional<ResultsSeal> verified = verify_results_seal(path);
  if (seal != nullptr) *seal = verified;
  std::error_code size_error;
  const auto bytes = std::filesystem::file_size(path, size_error);
  if (H5Fis_hdf5(path.c_str()) <= 0) {
    H5Eclear2(H5E_DEFAULT);
    throw std::runtime_error(
        "is not an HDF5 file (" +
        (size_error ? std::string("its size is unknown") : std::to_string(bytes) + " bytes") +
        "): another kind of file, or a results file damaged or cut short at "
        "its start");
  }
  // Closing the file closes whatever HDF5 left open inside it while failing on damaged metadata;
  // otherwise those objects outlive the file and HDF5 complains when the program ends.
  const h5::Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "cannot create property list");
  h5::check(H5Pset_fclose_degree(access.get(), H5F_CLOSE_STRONG), "cannot set the close degree");
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, access.get());
  if (id < 0) {
    try {
      h5::fail("HDF5 cannot open it");
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(std::string(e.what()) + " \u2014 the file is damaged");
    }
  }
  return h5::Handle(id, H5Fclose, "cannot open");
}

}  // namespace styk::io
