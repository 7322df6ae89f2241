/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later

Description
    RiserContact, part 3 of 3: the stepper of the particles sub-stepped without the mesh: their
    hand-over to the core's granular engine and back, with the halo of the
    other processors' particles (meshFreeContacts) (RiserContact.H, Description).

\*---------------------------------------------------------------------------*/

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
riser::PairContactState Foam::RiserContact<CloudType>::pairHandOver
(
    const grainPairSpring& s
)
{
    riser::PairContactState c;
    c.spring = toCore(s.spring);
    if (s.recorded)
    {
        c.force = toCore(s.force);
        c.forceKnown = true;
        c.approachSpeed = s.approachSpeed;
    }
    return c;
}


template<class CloudType>
void Foam::RiserContact<CloudType>::grainStates
(
    const UList<parcelType*>& parcels,
    const UList<linearisedAcceleration>& fluidAcceleration,
    const UList<vector>& startOffset,
    List<grainState>& grains,
    List<grainPairSpring>& springs
) const
{
    grains.setSize(parcels.size());
    DynamicList<grainPairSpring> pairSprings;
    forAll(parcels, i)
    {
        const parcelType& p = *parcels[i];
        grainState& m = grains[i];
        m = grainState();
        m.key = labelPair(p.origProc(), p.origId());
        m.processor = Pstream::myProcNo();
        m.x = p.position();
        m.xStart = m.x + startOffset[i];
        m.U = p.U();
        m.omega = rotation_ ? p.omega() : vector::zero;
        m.a = fluidAcceleration[i].a0;
        m.drag = fluidAcceleration[i].rate;
        m.Uc = fluidAcceleration[i].Uc;
        m.R = 0.5*p.d();
        m.mEff = effectiveMass(p);
        m.mP = p.mass();
        m.inertia = p.momentOfInertia();
        m.F = p.f()*(m.mEff/p.mass());
        m.T = rotation_ ? p.torque() : vector::zero;
        m.need = need(p).n;
        for (const auto& record : p.collisionRecords().wallRecords())
        {
            m.wallSpring = record.collisionData();
            m.touchingWall = true;
        }
        const contactsInProgress* carried = carriedContacts(*parcels[i]);
        for (const auto& record : p.collisionRecords().pairRecords())
        {
            grainPairSpring s;
            s.key = m.key;
            s.other = labelPair(record.origProcOfOther(), record.origIdOfOther());
            s.spring = record.collisionData();
            if (carried)
            {
                for (const pairContactRecord& r : carried->pairs)
                {
                    if (r.other == s.other)
                    {
                        s.recorded = true;
                        s.approachSpeed = r.approachSpeed;
                        s.force = r.force;
                    }
                }
            }
            pairSprings.append(s);
        }
    }
    springs.transfer(pairSprings);
}


template<class CloudType>
void Foam::RiserContact<CloudType>::haloOf
(
    const UList<grainState>& all,
    labelList& local,
    labelListList& send,
    labelListList& recv
) const
{
    const label me = Pstream::myProcNo();
    const label nProcs = Pstream::nProcs();
    std::vector<bool> inHalo(all.size(), false);
    // (processor, own particle in its halo), each possibly many times
    std::vector<std::pair<label, label>> sends;
    if (pairLaw_.valid() && nProcs > 1)
    {
        // the pairs of particles of two processors that may touch within
        // the step: each is in the other's halo (both processors evaluate
        // the same expression on the same numbers, so each finds the pair
        // alike, and what one sends the other expects)
        std::vector<riser::Vector> x(all.size());
        forAll(all, k)
        {
            x[k] = toCore(all[k].x);
        }
        forEachNearPair(x, pairCutoff(), [&](std::size_t a, std::size_t b, scalar)
        {
            const grainState& p = all[a];
            const grainState& q = all[b];
            if (p.processor == q.processor || (p.processor != me && q.processor != me))
            {
                return;
            }
            const scalar gap = pairGap(x[a], p.key, p.R, x[b], q.key, q.R);
            if (gap > pairReach(p.R, q.R))
            {
                return;
            }
            if (p.processor == me)
            {
                inHalo[b] = true;
                sends.emplace_back(q.processor, label(a));
            }
            else
            {
                inHalo[a] = true;
                sends.emplace_back(p.processor, label(b));
            }
        });
    }
    std::sort(sends.begin(), sends.end());
    sends.erase(std::unique(sends.begin(), sends.end()), sends.end());
    DynamicList<label> grains;
    forAll(all, k)
    {
        if (all[k].processor == me || inHalo[k])
        {
            grains.append(k);
        }
    }
    // in the order of their positions (by z, then x, then y), which does
    // not depend on the decomposition (the keys do: each processor numbers
    // the particles it injects), so that the contact forces are summed in
    // the same order in a serial and a parallel run, and a pair across
    // processors is evaluated alike on both
    std::sort
    (
        grains.begin(), grains.end(),
        [&all](label a, label b)
        {
            const vector& p = all[a].x;
            const vector& q = all[b].x;
            return
                p.z() < q.z()
             || (p.z() == q.z() && (p.x() < q.x() || (p.x() == q.x() && p.y() < q.y())));
        }
    );
    local.transfer(grains);
    labelList localOf(all.size(), -1);
    forAll(local, i)
    {
        localOf[local[i]] = i;
    }
    send.setSize(nProcs);
    recv.setSize(nProcs);
    List<DynamicList<label>> s(nProcs), r(nProcs);
    for (const std::pair<label, label>& ps : sends)
    {
        s[ps.first].append(localOf[ps.second]);
    }
    forAll(all, k)
    {
        if (inHalo[k])
        {
            r[all[k].processor].append(localOf[k]);
        }
    }
    for (label proc = 0; proc < nProcs; ++proc)
    {
        send[proc].transfer(s[proc]);
        recv[proc].transfer(r[proc]);
    }
}


template<class CloudType>
Foam::List<Foam::contactStep>
Foam::RiserContact<CloudType>::meshFreeContacts
(
    const UList<parcelType*>& parcels,
    const UList<linearisedAcceleration>& fluidAcceleration,
    const UList<vector>& startOffset
)
{
    const Time& time = this->owner().mesh().time();
    const riser::Wall& wall = riser_.wall();
    const scalar dt = time.deltaTValue();
    const scalar t0 = time.value() - dt;
    const label me = Pstream::myProcNo();
    const bool walls = wallLaw_.valid();

    // the group's particles at the step's start: this processor's (in the
    // order of parcels), then, with pairs, copies of the other processors'
    // near the box of its own (each processor's in its order), with their
    // pair springs
    List<grainState> all;
    List<grainPairSpring> springs;
    // what this processor sends the others in the step: bytes
    std::size_t bytesSent = 0;
    label nOwnGrains = 0;
    {
        List<grainState> own;
        List<grainPairSpring> ownSprings;
        grainStates(parcels, fluidAcceleration, startOffset, own, ownSprings);
        nOwnGrains = own.size();
        DynamicList<grainState> grains(own);
        DynamicList<grainPairSpring> pairSprings(ownSprings);
        if (pairLaw_.valid() && Pstream::parRun())
        {
            List<vector> x(own.size());
            HashTable<label, labelPair, labelPairHash> ownOf(2*own.size());
            forAll(own, i)
            {
                x[i] = own[i].x;
                ownOf.insert(own[i].key, i);
            }
            const labelListList send = nearProcessors
            (
                x, pairCutoff(), riser_.section().period()
            );
            // (the springs of the particles sent)
            List<labelList> sendSprings(send.size());
            forAll(send, proc)
            {
                if (send[proc].empty())
                {
                    continue;
                }
                std::vector<bool> sent(own.size(), false);
                for (const label i : send[proc])
                {
                    sent[i] = true;
                }
                DynamicList<label> k;
                forAll(ownSprings, s)
                {
                    if (sent[ownOf[ownSprings[s].key]])
                    {
                        k.append(s);
                    }
                }
                sendSprings[proc].transfer(k);
            }
            for (const List<grainState>& g : exchanged(send, own, bytesSent))
            {
                grains.append(g);
            }
            for (const List<grainPairSpring>& g : exchanged(sendSprings, ownSprings, bytesSent))
            {
                pairSprings.append(g);
            }
        }
        all.transfer(grains);
        springs.transfer(pairSprings);
    }
    // the explicit drag of the sub-steps stays stable: drag h <= 1 (the
    // same on every processor: the largest rate of the group's particles)
    label nDrag = 1;
    for (label i = 0; i < nOwnGrains; ++i)
    {
        nDrag = max(nDrag, label(ceil(all[i].drag*dt)));
    }
    reduce(nDrag, maxOp<label>());

    // this processor steps its own particles and its halo's copies of the
    // others' near them; after each move the copies are given the state
    // their processors moved them to
    labelList local;
    labelListList send, recv;
    haloOf(all, local, send, recv);
    const label n = local.size();

    // the parts: the particles that may touch each other within the step
    // (the plan's clusters as this processor sees them with its halo), each
    // with its cluster's need of sub-steps (the plan's: the same on every
    // processor that holds a part of the cluster), at least the drag's
    std::vector<long> partNeed(n);
    forAll(local, i)
    {
        partNeed[i] = max(max(all[local[i]].need, label(1)), nDrag);
    }
    riser::ClusterPlan parts(partNeed);
    if (pairLaw_.valid())
    {
        std::vector<riser::Vector> x(n);
        forAll(local, i)
        {
            x[i] = toCore(all[local[i]].x);
        }
        forEachNearPair(x, pairCutoff(), [&](std::size_t a, std::size_t b, scalar)
        {
            const grainState& p = all[local[a]];
            const grainState& q = all[local[b]];
            if (pairGap(x[a], p.key, p.R, x[b], q.key, q.R) <= pairReach(p.R, q.R))
            {
                parts.join(a, b, 0);
            }
        });
    }
    parts.spread(0);

    // the systems stepped: each part without copies of other processors'
    // particles on its own (its data stays in the cache over its
    // sub-steps, and it takes no more sub-steps than its own cluster
    // needs), and the parts with copies together by their need, exchanging
    // the copies' states with those processors after each move (every
    // processor steps these in the order of their needs, so that the
    // messages between two processors meet)
    std::vector<bool> withCopies(n, false);
    forAll(local, i)
    {
        if (all[local[i]].processor != me)
        {
            withCopies[parts.cluster(i)] = true;
        }
    }
    labelList systemOf(n, -1);
    DynamicList<DynamicList<label>> members;
    DynamicList<label> systemSubSteps;
    DynamicList<bool> systemExchanges;
    Map<label> exchangingByNeed;
    forAll(local, i)
    {
        const std::size_t root = parts.cluster(i);
        label& s = systemOf[root];
        if (s < 0)
        {
            const label need = parts.need(i);
            const auto found = exchangingByNeed.cfind(need);
            if (withCopies[root] && found.found())
            {
                s = *found;
            }
            else
            {
                s = members.size();
                members.append(DynamicList<label>());
                systemSubSteps.append(need);
                systemExchanges.append(withCopies[root]);
                if (withCopies[root])
                {
                    exchangingByNeed.insert(need, s);
                }
            }
        }
        members[s].append(i);
    }
    // (the systems without exchange first, then those with, by need)
    labelList order(identity(members.size()));
    std::stable_sort
    (
        order.begin(), order.end(),
        [&](label a, label b)
        {
            return
                systemExchanges[a] == systemExchanges[b]
              ? systemExchanges[a] && systemSubSteps[a] < systemSubSteps[b]
              : !systemExchanges[a];
        }
    );

    // each particle's key to its place in local, and the pair springs
    // handed over by each particle
    HashTable<label, labelPair, labelPairHash> grainOf(2*n);
    forAll(local, i)
    {
        grainOf.insert(all[local[i]].key, i);
    }
    labelListList springsOf(n);
    {
        labelList count(n, 0);
        forAll(springs, s)
        {
            const auto i = grainOf.cfind(springs[s].key);
            if (i.found())
            {
                ++count[*i];
            }
        }
        forAll(springsOf, i)
        {
            springsOf[i].setSize(count[i]);
            count[i] = 0;
        }
        forAll(springs, s)
        {
            const auto i = grainOf.cfind(springs[s].key);
            if (i.found())
            {
                springsOf[*i][count[*i]++] = s;
            }
        }
    }

    auto optionalLaw = [](const autoPtr<riser::HertzMindlin>& law)
    {
        return
            law.valid()
          ? std::optional<riser::HertzMindlin>(law())
          : std::optional<riser::HertzMindlin>();
    };
    // (all holds this processor's particles first, in the order of
    // parcels)
    const label firstOwn = 0;
    List<contactStep> ownSteps(parcels.size());
    label pairsInContact = 0, acrossProcessors = 0, exchangesDone = 0;
    // the place of a particle of local in the system being stepped
    labelList posOf(n, -1);

    // one system over the step: its grains (places in local, in order),
    // sub-steps, and whether it exchanges copies' states
    auto stepSystem = [&](const UList<label>& grainsIn, const label nSub, const bool exchanges)
    {
        const label M = grainsIn.size();
        const scalar h = dt/nSub;
        forAll(grainsIn, a)
        {
            posOf[grainsIn[a]] = a;
        }
        riser::GranularSystem grains
        (
            optionalLaw(pairLaw_), optionalLaw(wallLaw_), riser::Vector::Zero(),
            rotation_
        );
        if (walls)
        {
            grains.addWall(wall);
        }
        if (riser_.section().periodic)
        {
            grains.setPeriodic(riser_.section().z0, riser_.section().length);
        }
        grains.setTime(t0);
        // the own grains without contacts: their free motion under the
        // fluid acceleration, integrated alike (a grain that touches nothing
        // moves exactly as its free one)
        riser::GranularSystem free(std::nullopt, std::nullopt, riser::Vector::Zero(), rotation_);
        std::vector<riser::Vector> grainF(M), grainT(M);
        // the own grains: grain index, parcel and free grain
        DynamicList<label> ownGrain(M);
        DynamicList<parcelType*> ownParcel(M);
        labelList ownIndex(M, -1);
        forAll(grainsIn, a)
        {
            const grainState& m = all[local[grainsIn[a]]];
            riser::Grain g{toCore(m.xStart), toCore(m.U), toCore(m.omega), m.R, m.mEff};
            g.accel = toCore(m.a);
            g.drag = m.drag;
            g.carrierVelocity = toCore(m.Uc);
            g.inertia = m.inertia;
            grains.addGrain(g);
            grainF[a] = toCore(m.F);
            grainT[a] = toCore(m.T);
            if (m.processor == me)
            {
                free.addGrain(g);
                ownIndex[a] = ownGrain.size();
                ownGrain.append(a);
                ownParcel.append(parcels[local[grainsIn[a]] - firstOwn]);
            }
        }
        forAll(grainsIn, a)
        {
            const grainState& m = all[local[grainsIn[a]]];
            if (walls && m.touchingWall)
            {
                // with the force of its last evaluation, when its particle
                // is this processor's (for its dissipation tally)
                const wallContactRecord* e =
                    ownIndex[a] >= 0 ? wallRecord(*ownParcel[ownIndex[a]]) : nullptr;
                if (e)
                {
                    grains.setWallContact
                    (
                        a, 0, toCore(m.wallSpring), toCore(e->force), e->normalSpeedIn
                    );
                }
                else
                {
                    grains.setWallSpring(a, 0, toCore(m.wallSpring));
                }
            }
            for (const label s : springsOf[grainsIn[a]])
            {
                // each pair once, from the record of the particle first in
                // order (the spring in its frame), with what that particle
                // carries of it
                const auto j = grainOf.cfind(springs[s].other);
                if (j.found() && grainsIn[a] < *j && posOf[*j] >= 0)
                {
                    grains.setPairContact(a, posOf[*j], pairHandOver(springs[s]));
                }
            }
        }
        grains.setContactForces(grainF, grainT);

        // the halo's copies given their processors' state after each move
        // (each processor knows what it sends and receives: messages of
        // known sizes, posted at once, without a collective)
        labelListList sendHere(send.size()), recvHere(recv.size());
        bool traffic = false;
        if (exchanges)
        {
            forAll(send, proc)
            {
                DynamicList<label> s, r;
                for (const label i : send[proc])
                {
                    if (posOf[i] >= 0) s.append(posOf[i]);
                }
                for (const label i : recv[proc])
                {
                    if (posOf[i] >= 0) r.append(posOf[i]);
                }
                sendHere[proc].transfer(s);
                recvHere[proc].transfer(r);
                traffic = traffic || sendHere[proc].size() || recvHere[proc].size();
            }
        }
        List<List<vector>> outgoing(sendHere.size()), incoming(recvHere.size());
        forAll(sendHere, proc)
        {
            outgoing[proc].setSize(3*sendHere[proc].size());
            incoming[proc].setSize(3*recvHere[proc].size());
        }
        auto exchangeHalo = [&](std::vector<riser::Grain>& g)
        {
            if (!traffic)
            {
                return;
            }
            ++exchangesDone;
            const label requests = UPstream::nRequests();
            forAll(recvHere, proc)
            {
                if (recvHere[proc].size())
                {
                    UIPstream::read
                    (
                        Pstream::commsTypes::nonBlocking, proc,
                        reinterpret_cast<char*>(incoming[proc].data()),
                        incoming[proc].byteSize()
                    );
                }
            }
            forAll(sendHere, proc)
            {
                List<vector>& state = outgoing[proc];
                forAll(sendHere[proc], s)
                {
                    const riser::Grain& p = g[sendHere[proc][s]];
                    state[3*s] = fromCore(p.x);
                    state[3*s + 1] = fromCore(p.v);
                    state[3*s + 2] = fromCore(p.omega);
                }
                if (state.size())
                {
                    UOPstream::write
                    (
                        Pstream::commsTypes::nonBlocking, proc,
                        reinterpret_cast<const char*>(state.cdata()), state.byteSize()
                    );
                    bytesSent += state.byteSize();
                }
            }
            UPstream::waitRequests(requests);
            forAll(recvHere, proc)
            {
                const List<vector>& state = incoming[proc];
                forAll(recvHere[proc], r)
                {
                    riser::Grain& p = g[recvHere[proc][r]];
                    p.x = toCore(state[3*r]);
                    p.v = toCore(state[3*r + 1]);
                    p.omega = toCore(state[3*r + 2]);
                }
            }
        };

        // the sub-steps; the own particles' wall contacts in progress, as
        // collide() keeps them
        std::vector<bool> inContact(ownGrain.size());
        forAll(ownGrain, i)
        {
            inContact[i] = wallRecord(*ownParcel[i]) != nullptr;
        }
        List<contactTrace> trace(ownGrain.size());
        for (label k = 1; k <= nSub; ++k)
        {
            grains.step(h, exchangeHalo);
            free.step(h);
            const scalar t = t0 + k*h;
            ledger_.pairOverlap(grains.largestPairOverlap());
            forAll(ownGrain, i)
            {
                if (!walls)
                {
                    break;
                }
                const label gi = ownGrain[i];
                const riser::WallContactState& c = grains.wallContact(gi, 0);
                if (!c.touching && !inContact[i])
                {
                    continue;
                }
                const labelPair& key = all[local[grainsIn[gi]]].key;
                const riser::Grain& g = grains.grains()[gi];
                const riser::ContactPoint cp = wall.contactPoint(g.x, g.radius, t);
                const vector nw = fromCore(cp.normal);
                // (the velocity the force was evaluated with, as a tracked
                // particle's collide() sees it: the half-step one)
                const vector Urel = fromCore(c.velocity);
                const vector spin = fromCore(g.omega);
                if (c.touching)
                {
                    ledger_.checkInside(key, c.overlap, g.radius, t);
                    contactLedger::wallContactGoesOn
                    (
                        *wallRecord(*ownParcel[i], true), t, h, c.overlap, fromCore(c.force),
                        c.normalForce, Urel, nw, spin
                    );
                    inContact[i] = true;
                }
                else
                {
                    wallContactEnds(*ownParcel[i], trace[i], t, Urel, nw, spin);
                    inContact[i] = false;
                }
            }
        }

        // The contact trace of the flow step (contactTrace.H) of each own
        // particle, its wall contact's last force, springs; and what the
        // contacts added to its free motion
        forAll(ownGrain, i)
        {
            const label gi = ownGrain[i];
            const grainState& m = all[local[grainsIn[gi]]];
            parcelType& p = *ownParcel[i];
            const riser::Grain& g = grains.grains()[gi];
            const riser::Grain& gFree = free.grains()[i];
            trace[i].wallEnergy = grains.wallEnergy(gi);
            trace[i].recordPairContacts
            (
                label(grains.pairContactsCompleted(gi)), grains.pairImpactSpeed(gi)
            );
            trace[i].pairEnergy = grains.pairEnergy(gi);
            addContactTrace(p, trace[i]);
            p.collisionRecords() =
                typename std::decay<decltype(p.collisionRecords())>::type();
            if (walls)
            {
                const riser::WallContactState& c = grains.wallContact(gi, 0);
                wallContactRecord* e = wallRecord(p);
                if (c.touching && e)
                {
                    e->force = fromCore(c.force);
                    e->normal = fromCore(c.normal);
                    e->wallVelocity = fromCore(c.wallVelocity);
                }
                if (c.touching)
                {
                    const riser::ContactPoint cp =
                        wall.contactPoint(g.x, g.radius, time.value());
                    p.collisionRecords().matchWallRecord
                    (
                        0.99*g.radius*fromCore(cp.normal), g.radius
                    ).collisionData() = fromCore(grains.wallSpring(gi, 0));
                }
            }
            // the track from the particle's position, x + U dt, is given
            // what puts it where the engine left it (up to the track's own
            // share of the fluid's a dt^2/2: RiserCloud); the velocity gets
            // the contacts' change on top of the fluid forces' own
            contactStep c;
            c.x = fromCore(g.x);
            c.dx = c.x - m.x - dt*m.U;
            c.dU = fromCore(riser::Vector(g.v - gFree.v));
            c.dL = m.inertia*fromCore(riser::Vector(g.omega - gFree.omega));
            c.f = (m.mP/m.mEff)*fromCore(grains.contactForce(gi));
            c.torque = rotation_ ? fromCore(grains.contactTorque(gi)) : vector::zero;
            ownSteps[local[grainsIn[gi]] - firstOwn] = c;
        }

        // the pair contacts in progress: each own particle's springs, and
        // its record of them (contactsInProgress.H: carried to the next
        // step, to another processor, across a restart), renewed
        for (parcelType* p : ownParcel)
        {
            if (contactsInProgress* carried = carriedContacts(*p))
            {
                carried->pairs.clear();
            }
        }
        grains.forEachPairContactState
        (
            [&](std::size_t i, std::size_t j, const riser::PairContactState& state)
            {
                const grainState& a = all[local[grainsIn[i]]];
                const grainState& b = all[local[grainsIn[j]]];
                // (the state is i's: its spring, and the force on i)
                auto keep = [&state](parcelType& p, const labelPair& other, const scalar sign)
                {
                    p.collisionRecords()
                        .matchPairRecord(other.first(), other.second())
                        .collisionData() = sign*fromCore(state.spring);
                    if (contactsInProgress* carried = carriedContacts(p))
                    {
                        pairContactRecord r;
                        r.other = other;
                        r.approachSpeed = state.approachSpeed;
                        r.force = sign*fromCore(state.force);
                        carried->pairs.append(r);
                    }
                };
                if (a.processor == me)
                {
                    keep(*ownParcel[ownIndex[i]], b.key, 1);
                    ++pairsInContact;
                    acrossProcessors += a.processor != b.processor;
                }
                if (b.processor == me)
                {
                    keep(*ownParcel[ownIndex[j]], a.key, -1);
                }
            }
        );
        forAll(grainsIn, a)
        {
            posOf[grainsIn[a]] = -1;
        }
    };
    for (const label s : order)
    {
        stepSystem(members[s], systemSubSteps[s], systemExchanges[s]);
    }
    for (parcelType* p : parcels)
    {
        // as after collide(): kept, marked not accessed
        p->collisionRecords().update();
    }
    if (Pstream::parRun())
    {
        Info<< "    riserContact: "
            << returnReduce(pairsInContact, sumOp<label>()) << " pair(s) in contact, "
            << returnReduce(acrossProcessors, sumOp<label>())
            << " across processor boundaries; sent copies of "
            << returnReduce(label(all.size()) - nOwnGrains, sumOp<label>())
            << " particle(s) and their states in the sub-steps, "
            << returnReduce(scalar(bytesSent), sumOp<scalar>()) << " bytes, at most "
            << returnReduce(exchangesDone, maxOp<label>())
            << " exchanges of states by a processor" << endl;
    }

    return ownSteps;
}


// ************************************************************************* //
