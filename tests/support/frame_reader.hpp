#pragma once
// A run's frames read back: blocks, points and counts.

#include <cstdio>
#include <filesystem>
#include <string>
#include <vtkCompositeDataSet.h>
#include <vtkDataSet.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLMultiBlockDataReader.h>

namespace grainload::testing {

/// The frame `index` a run into `out` wrote for the case called `name` (its [case] name, the
/// file's stem): out/frames/NAME_000012.vtm.
inline std::string frame_path(const std::string& out, const std::string& name, int index) {
    char number[16];
    std::snprintf(number, sizeof number, "_%06d.vtm", index);
    return out + "/frames/" + name + number;
}

/// Block `index` of a written frame (.vtm) as VTK's own reader returns it: a particle body.
inline vtkSmartPointer<vtkPolyData> read_particle_block(const std::string& vtm,
                                                        unsigned index = 0) {
    vtkNew<vtkXMLMultiBlockDataReader> reader;
    reader->SetFileName(vtm.c_str());
    reader->Update();
    auto* blocks = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
    return vtkPolyData::SafeDownCast(blocks->GetBlock(index));
}

/// The block called `name` (a body, a wall, a shell part) of a written frame; null if none.
inline vtkSmartPointer<vtkDataSet> read_named_block(const std::string& vtm,
                                                    const std::string& name) {
    vtkNew<vtkXMLMultiBlockDataReader> reader;
    reader->SetFileName(vtm.c_str());
    reader->Update();
    auto* blocks = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
    for (unsigned i = 0; blocks != nullptr && i < blocks->GetNumberOfBlocks(); ++i) {
        if (blocks->HasMetaData(i) &&
            name == blocks->GetMetaData(i)->Get(vtkCompositeDataSet::NAME())) {
            return vtkDataSet::SafeDownCast(blocks->GetBlock(i));
        }
    }
    return nullptr;
}

/// How many points of the block `name`, over every frame (.vtm) of the run in `out`, satisfy
/// `outside(point)`: a check that holds in all frames expects 0.
template <class Predicate>
long count_frame_points(const std::string& out, const std::string& name, Predicate outside) {
    long count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(out + "/frames")) {
        if (entry.path().extension() != ".vtm") {
            continue;
        }
        const auto block = read_named_block(entry.path().string(), name);
        for (vtkIdType i = 0; block != nullptr && i < block->GetNumberOfPoints(); ++i) {
            count += outside(block->GetPoint(i)) ? 1 : 0;
        }
    }
    return count;
}

} // namespace grainload::testing
