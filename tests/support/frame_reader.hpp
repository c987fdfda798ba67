#pragma once

#include <string>
#include <vtkMultiBlockDataSet.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLMultiBlockDataReader.h>

namespace grainload::testing {

/// Block `index` of a written frame (.vtm) as VTK's own reader returns it: a particle body.
inline vtkSmartPointer<vtkPolyData> read_particle_block(const std::string& vtm,
                                                        unsigned index = 0) {
    vtkNew<vtkXMLMultiBlockDataReader> reader;
    reader->SetFileName(vtm.c_str());
    reader->Update();
    auto* blocks = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
    return vtkPolyData::SafeDownCast(blocks->GetBlock(index));
}

} // namespace grainload::testing
