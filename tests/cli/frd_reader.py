"""An independent reader of CalculiX .frd result files (ASCII), written from the format's
description in the CalculiX GraphiX manual ("Result Format"): fixed columns, a record's key in its
first columns. It reads the node block (2C), the element block (3C) and the nodal result blocks
(1PSTEP, 100C, -4, -5, -1 ... -3), and checks what the format promises: counts, element node
counts per type, a closing 9999."""

# Nodes per element of each .frd element type (cgx's types 1-12).
NODES_PER_TYPE = {1: 8, 2: 6, 3: 4, 4: 20, 5: 15, 6: 10, 7: 3, 8: 6, 9: 4, 10: 8, 11: 2, 12: 3}


class FrdError(Exception):
    pass


class Block:
    def __init__(self, step, increment, time, name, components):
        self.step = step
        self.increment = increment
        self.time = time
        self.name = name
        self.components = components
        self.values = {}  # node id -> list of floats


class Frd:
    def __init__(self):
        self.nodes = {}      # id -> (x, y, z)
        self.elements = {}   # id -> (type, [node ids])
        self.blocks = []     # Block, in file order
        self.ended = False


def _ints(text, width):
    return [int(text[i:i + width]) for i in range(0, len(text.rstrip()), width)]


def _floats(text, count):
    return [float(text[i * 12:(i + 1) * 12]) for i in range(count)]


def read_frd(path):
    frd = Frd()
    with open(path) as f:
        lines = f.read().split("\n")
    i = 0
    step_param = None
    header = None
    while i < len(lines):
        line = lines[i]
        key = line[:6]
        if line.strip() == "":
            i += 1
            continue
        if line.startswith(" 9999"):
            frd.ended = True
            break
        if key in ("    1C", "    1U"):
            i += 1
        elif key == "    2C":
            count = int(line[24:36])
            if int(line[73:75]) != 1:
                raise FrdError("%s: only the long format (1) is read" % path)
            i += 1
            while not lines[i].startswith(" -3"):
                if not lines[i].startswith(" -1"):
                    raise FrdError("%s:%d: a node record must start with -1" % (path, i + 1))
                frd.nodes[int(lines[i][3:13])] = tuple(_floats(lines[i][13:], 3))
                i += 1
            if len(frd.nodes) != count:
                raise FrdError("%s: %d nodes, the block says %d" % (path, len(frd.nodes), count))
            i += 1
        elif key == "    3C":
            count = int(line[24:36])
            i += 1
            while not lines[i].startswith(" -3"):
                rec = lines[i]
                if not rec.startswith(" -1"):
                    raise FrdError("%s:%d: an element record must start with -1" % (path, i + 1))
                eid, etype = int(rec[3:13]), int(rec[13:18])
                if etype not in NODES_PER_TYPE:
                    raise FrdError("%s:%d: unknown element type %d" % (path, i + 1, etype))
                nodes = []
                i += 1
                while len(nodes) < NODES_PER_TYPE[etype]:
                    if not lines[i].startswith(" -2"):
                        raise FrdError("%s:%d: element %d lacks nodes" % (path, i + 1, eid))
                    nodes += _ints(lines[i][3:], 10)
                    i += 1
                if len(nodes) != NODES_PER_TYPE[etype]:
                    raise FrdError("element %d: %d nodes for type %d" % (eid, len(nodes), etype))
                frd.elements[eid] = (etype, nodes)
            if len(frd.elements) != count:
                raise FrdError("%s: %d elements, the block says %d" % (path, len(frd.elements), count))
            i += 1
        elif key == "    1P":
            # 1PSTEP: block counter, increment, step
            step_param = (int(line[36:48]), int(line[48:60]))
            i += 1
        elif key == "  100C":
            header = line
            time = float(line[12:24])
            count = int(line[24:36])
            name_line = lines[i + 1]
            if not name_line.startswith(" -4"):
                raise FrdError("%s:%d: a -4 record must follow 100C" % (path, i + 2))
            name = name_line[5:13].strip()
            ncomp = int(name_line[13:18])
            i += 2
            components = []
            while lines[i].startswith(" -5"):
                # IEXIST = 1 (columns 34-38): a component the post-processor computes (ALL, the
                # vector's magnitude), which has no values in the records.
                exists = lines[i][33:38].strip()
                if exists in ("", "0"):
                    components.append(lines[i][5:13].strip())
                i += 1
            if step_param is None:
                raise FrdError("%s: a result block without 1PSTEP" % path)
            if len(components) > ncomp:
                raise FrdError("%s: block %s lists more components than its -4 record" % (path, name))
            block = Block(step_param[1], step_param[0], time, name, components)
            while not lines[i].startswith(" -3"):
                rec = lines[i]
                if not rec.startswith(" -1"):
                    raise FrdError("%s:%d: a value record must start with -1" % (path, i + 1))
                block.values[int(rec[3:13])] = _floats(rec[13:], len(components))
                i += 1
            if len(block.values) != count:
                raise FrdError("%s: block %s holds %d nodes, its header says %d"
                               % (path, name, len(block.values), count))
            for nid in block.values:
                if nid not in frd.nodes:
                    raise FrdError("%s: block %s names node %d, which is not a node" % (path, name, nid))
            frd.blocks.append(block)
            i += 1
        else:
            raise FrdError("%s:%d: unknown record '%s'" % (path, i + 1, line[:10]))
    if not frd.ended:
        raise FrdError("%s: no closing 9999 record" % path)
    for eid, (etype, nodes) in frd.elements.items():
        for n in nodes:
            if n not in frd.nodes:
                raise FrdError("%s: element %d names node %d, which is not a node" % (path, eid, n))
    return frd
