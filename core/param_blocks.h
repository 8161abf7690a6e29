// Where a module keeps the parameters it owns inside TreeParams: one block (a plain struct
// such as colonization's ColonizationParams) per type, so core holds a growth method's
// parameters without knowing them. A block never stored reads as its defaults (Block{}).
//
// Copies share blocks until one of them is edited (copy-on-write), so a TreeParams stays a
// cheap value to hand to worker threads. Not thread-safe for one object: like any value,
// one TreeParams may be read from many threads but written from one, with no reader then.
#pragma once

#include <memory>
#include <typeindex>
#include <utility>
#include <vector>

namespace sylva {

class ParamBlocks {
  public:
    // The stored block of this type, or a default one. The reference lasts until the next
    // edit<Block>() of this object.
    template <class Block>
    const Block& get() const {
        for (const auto& [type, block] : blocks_)
            if (type == typeid(Block)) return *static_cast<const Block*>(block.get());
        static const Block defaults{};
        return defaults;
    }

    // The block of this type to change, this object's own (a block shared with a copy is
    // copied first; one never stored starts as Block{}).
    template <class Block>
    Block& edit() {
        for (auto& [type, block] : blocks_) {
            if (type != typeid(Block)) continue;
            if (block.use_count() > 1)
                block = std::make_shared<Block>(*static_cast<const Block*>(block.get()));
            return *static_cast<Block*>(block.get());
        }
        auto& added =
            blocks_.emplace_back(std::type_index(typeid(Block)), std::make_shared<Block>());
        return *static_cast<Block*>(added.second.get());
    }

  private:
    std::vector<std::pair<std::type_index, std::shared_ptr<void>>> blocks_;
};

}  // namespace sylva
